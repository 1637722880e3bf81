#!/usr/bin/env bash
# run-fuzzers.sh TREE SECONDS TARGET...: each libFuzzer target fuzz_TARGET of the build tree
# TREE for SECONDS, two at a time: a fuzzer is one process on one core, and CI has two, so
# the fuzz stage of make test takes half the wall time it would one after the other
# (docs/testing.md, "Time"). New inputs go to TREE/corpus/TARGET; the committed seeds in
# fuzz/corpus/TARGET are only read; fuzz/TARGET.dict is used when there is one. Each
# fuzzer's output is printed when it ends; any crash or failure fails the run.
set -uo pipefail
tree=$1 seconds=$2
shift 2
logs=$(mktemp -d "${TMPDIR:-/tmp}/feel-fuzz.XXXXXX")
trap 'rm -rf "$logs"' EXIT

start() {  # start TARGET: in the background, its pid in $!
    local target=$1 dict=()
    mkdir -p "$tree/corpus/$target"
    [[ -f fuzz/$target.dict ]] && dict=(-dict="fuzz/$target.dict")
    "$tree/fuzz/fuzz_$target" -max_total_time="$seconds" -print_final_stats=1 "${dict[@]}" \
        "$tree/corpus/$target" "fuzz/corpus/$target" > "$logs/$target.log" 2>&1 &
}

failed=()
while (($#)); do
    batch=("$1")
    start "$1"
    pids=($!)
    if (($# > 1)); then
        batch+=("$2")
        start "$2"
        pids+=($!)
    fi
    for i in "${!batch[@]}"; do
        wait "${pids[$i]}"
        rc=$?
        echo "==== fuzz_${batch[$i]}: $seconds s, exit $rc"
        cat "$logs/${batch[$i]}.log"
        ((rc == 0)) || failed+=("fuzz_${batch[$i]}")
    done
    shift "${#batch[@]}"
done
if ((${#failed[@]})); then
    echo "fuzz: failed: ${failed[*]}" >&2
    exit 1
fi

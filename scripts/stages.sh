#!/usr/bin/env bash
# stages.sh STAGE...: make test's stages, one make target after the other, each timed, so
# that CI's log shows where its time goes (docs/testing.md, "Time"): a line per stage as it
# ends, and a table of all of them at the end, also when a stage fails (the first failure
# stops the run, as one make would). MAKE is the calling make (the Makefile passes
# $(MAKE)), so its variables (BUILD=..., CI=...) reach every stage.
set -uo pipefail
make_cmd=${MAKE:-make}
started=$(date +%s)
table=()
status=0
for stage in "$@"; do
    t0=$(date +%s)
    echo "==== stage $stage"
    $make_cmd --no-print-directory "$stage" || status=$?
    seconds=$(($(date +%s) - t0))
    outcome=ok
    ((status == 0)) || outcome="FAILED (exit $status)"
    table+=("$(printf '%-14s %5d s  %s' "$stage" "$seconds" "$outcome")")
    echo "==== stage $stage: $seconds s, $outcome"
    ((status == 0)) || break
done
echo "==== make test, wall time per stage"
printf '%s\n' "${table[@]}"
printf '%-14s %5d s\n' total $(($(date +%s) - started))
exit $status

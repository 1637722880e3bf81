#!/usr/bin/env bash
# stages.sh STAGE[~SECONDS]...: make test's stages, one make target after the other, each
# timed, so that CI's log shows where its time goes (docs/testing.md, "Time"): a line per
# stage as it ends, and a table of all of them at the end, also when a stage fails (the
# first failure stops the run, as one make would). MAKE is the calling make (the Makefile
# passes $(MAKE)), so its variables (BUILD=..., CI=...) reach every stage.
#
# The time budget: CI must end within its 40 minutes. A stage written STAGE~SECONDS (its
# expected wall time on CI's machine) is skipped, loudly, when STAGE_BUDGET_S is set and the
# time used so far plus SECONDS would pass it: a slow machine then loses that stage's
# checks, not the whole run. Stages without ~SECONDS always run.
set -uo pipefail
make_cmd=${MAKE:-make}
budget=${STAGE_BUDGET_S:-}
started=$(date +%s)
table=()
status=0
for spec in "$@"; do
    stage=${spec%%~*}
    expected=
    [[ $spec == *~* ]] && expected=${spec#*~}
    used=$(($(date +%s) - started))
    if [[ -n $budget && -n $expected ]] && ((used + expected > budget)); then
        echo "==== stage $stage: SKIPPED for time: $used s used, it needs about $expected s, the budget is $budget s"
        table+=("$(printf '%-14s %5s    %s' "$stage" "-" "SKIPPED (time budget: $used s used + about $expected s > $budget s)")")
        continue
    fi
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

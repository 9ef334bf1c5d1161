#!/bin/sh
# tests/fuzz/run.sh -- run the libFuzzer targets `make fuzz` built
# See LICENSE for copyright and license.
#
# Usage: sh tests/fuzz/run.sh PIPETRACE DIR SECONDS TARGET...
# Seeds each TARGET (scene, obj, trace, image) from the examples, the traces
# and images PIPETRACE makes of them, and tests/fuzz/corpus/TARGET/, then runs
# DIR/fuzz_TARGET for SECONDS.  New inputs go to DIR/corpus/TARGET, a finding
# to DIR/crash-TARGET-*; the last lines of each run are its figures.  A finding
# is fixed, then copied into tests/fuzz/corpus/TARGET/ (make test replays it).
exe=$1; dir=$2; secs=$3; shift 3
status=0
for t in "$@"; do
    seeds=$dir/seeds/$t
    rm -rf "$seeds"; mkdir -p "$seeds" "$dir/corpus/$t"
    case $t in
    scene) cp docs/examples/*.scene tests/data/*.scene "$seeds/" ;;
    obj)   cp docs/examples/*.obj tests/data/*.obj tests/data/*.OBJ "$seeds/" ;;
    trace) for s in docs/examples/*.scene; do
               b=$(basename "$s" .scene)
               [ "$(wc -c < "traces/$b.trace")" -lt 20000 ] || continue
               cp "traces/$b.trace" "$seeds/$b.trace"
               "$exe" "$s" --format jsonl > "$seeds/$b.jsonl"
           done
           cp tests/data/diff/*.jsonl "$seeds/" ;;
    image) "$exe" docs/examples/triangle.scene --image "$seeds/triangle.ppm" --trace /dev/null
           "$exe" docs/examples/triangle.scene --image "$seeds/triangle.png" --trace /dev/null ;;
    esac
    echo "== fuzz_$t for $secs s"
    nice "$dir/fuzz_$t" -max_total_time="$secs" -print_final_stats=1 \
        -artifact_prefix="$dir/crash-$t-" "$dir/corpus/$t" "$seeds" "tests/fuzz/corpus/$t" \
        > "$dir/fuzz_$t.log" 2>&1 || status=1
    grep -E '^#[0-9]+[[:space:]]+DONE|stat::number_of_executed_units|stat::average_exec_per_sec|ERROR|SUMMARY' \
        "$dir/fuzz_$t.log"
done
exit $status

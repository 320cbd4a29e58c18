#!/usr/bin/env bash
# Fuzzes every mesh reader, the model-file reader and the label-image reader (nii, nii.gz, nrrd, mha) with libFuzzer (clang-14, ASan + UBSan + float-cast-overflow) for SECONDS each, starting
# from the committed seed corpora in tests/fuzz/corpus/FORMAT (copied: new inputs go to build/fuzz/corpus, the
# committed ones are not touched). Limits: 10 s per input (a hang), 64 MB per allocation and 1 GB of RSS (a declared
# count that is not checked against the file's size), inputs up to 64 KB. A finding is written to
# build/fuzz/findings/FORMAT and fails the script; commit it to tests/fuzz/regressions/FORMAT/, which the unit tests
# read. The fuzzers run as many at a time as there are cores (each is single-threaded); the readers are compiled as a
# unity build. Usage: scripts/fuzz.sh [SECONDS=20] [FORMAT...]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-20}
shift || true
formats=${*:-msh vtu tetgen obj off stl model nii nii.gz nrrd mha}
out=build/fuzz
mkdir -p "$out"
CXX=clang++-14 cmake -S tests/fuzz -B "$out" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_UNITY_BUILD=ON \
  > "$out/configure.log" 2>&1 ||
  { tail -n 40 "$out/configure.log"; exit 1; }
cmake --build "$out" -j "$(nproc)" > "$out/build.log" 2>&1 || { tail -n 40 "$out/build.log"; exit 1; }
fuzz_one() {  # fuzz_one FORMAT: runs its fuzzer, prints one line, returns 1 on a finding
  local f=$1 log="$out/fuzz_$1.log"
  mkdir -p "$out/corpus/$f" "$out/findings/$f"
  cp -n tests/fuzz/corpus/"$f"/* "$out/corpus/$f/" 2>/dev/null || true
  cp -n tests/data/images/seed."$f" "$out/corpus/$f/" 2>/dev/null || true  # a label image's seed: the unit tests'
  # ITK (Debian's, not instrumented) keeps buffers for the process and leaks some on its error paths: the unit tests'
  # suppressions, with full malloc stacks so that they can see ITK's frames.
  if ASAN_OPTIONS=fast_unwind_on_malloc=0 LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp" "$out/fuzz_${f/./_}" "$out/corpus/$f" -max_total_time="$seconds" -timeout=10 -malloc_limit_mb=64 -rss_limit_mb=1024 \
       -max_len=65536 -artifact_prefix="$out/findings/$f/" -print_final_stats=1 > "$log" 2>&1; then
    runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$')
    peak=$(grep -o 'stat::peak_rss_mb: *[0-9]*' "$log" | grep -o '[0-9]*$')
    echo "fuzz $f: ${runs:-?} inputs in ${seconds} s, no finding, peak RSS ${peak:-?} MB"
  else
    echo "fuzz $f: FINDING (see $log and $out/findings/$f)"
    tail -n 30 "$log"
    return 1
  fi
}
status=0
pids=()
for f in $formats; do
  while [ "$(jobs -rp | wc -l)" -ge "$(nproc)" ]; do sleep 0.2; done
  fuzz_one "$f" &
  pids+=($!)
done
for pid in "${pids[@]}"; do wait "$pid" || status=1; done
exit $status

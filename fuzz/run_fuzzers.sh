#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/CMakeLists.txt) with clang, AddressSanitizer
# and UndefinedBehaviorSanitizer into BUILD_DIR, and runs each for SECONDS on a
# copy of its committed seed corpus (fuzz/corpus/<reader>; the collection
# seed is indexed from datasets/eight.off by the program REEB names, else by
# this build's reeb: tools/run check passes its sanitized build's). A crash, leak,
# sanitizer report, timeout (10 s per input) or out-of-memory (2 GiB) stops the
# run with exit 1 and leaves the input in BUILD_DIR/artifacts/: turn it into a
# regression test. A malloc of over 2 GiB returns NULL, as when memory runs
# out (allocator_may_return_null): HDF5 allocates the size a block of the file
# declares before it can check the block, and fails cleanly on NULL, which
# the reader turns into an Error; reebkit's own allocations (operator new)
# are still reported. `bash tools/run check` calls this after the sanitized suite.
#
#   fuzz/run_fuzzers.sh BUILD_DIR [SECONDS]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:?usage: fuzz/run_fuzzers.sh BUILD_DIR [SECONDS]}
seconds=${2:-30}
jobs=${JOBS:-$(nproc)}
readers=(off obj ply stl classes psbmatrix shrecmatrix collection)

start=$SECONDS
echo "== configure ($build: clang, libFuzzer, AddressSanitizer + UndefinedBehaviorSanitizer)"
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DREEBKIT_FUZZ=ON \
  -DREEBKIT_WARNINGS_AS_ERRORS=ON -DREEBKIT_BUILD_TESTS=OFF -DREEBKIT_BUILD_BENCH=OFF \
  -DREEBKIT_BUILD_EXPERIMENTS=OFF \
  -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
echo "== build (-j$jobs)"
targets=("${readers[@]/#/fuzz_}")
[ -n "${REEB:-}" ] || targets+=(reeb)
reeb=${REEB:-$build/tools/reeb}
cmake --build "$build" -j "$jobs" --target "${targets[@]}"
echo "== the fuzz build took $((SECONDS - start)) s"
start=$SECONDS

mkdir -p "$build/artifacts"
for reader in "${readers[@]}"; do
  corpus=$build/corpus/$reader
  mkdir -p "$corpus"
  cp -n "$root/fuzz/corpus/$reader"/* "$corpus/" 2>/dev/null || true
  if [ "$reader" = collection ]; then  # indexed anew: a seed of an older layout is only refused
    ASAN_OPTIONS=detect_leaks=0 "$reeb" index "$root/datasets/eight.off" -o "$corpus/eight.h5" \
      --threads 1 >/dev/null
  fi
  echo "== fuzz_$reader: $seconds s"
  ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1:max_allocation_size_mb=2048 LSAN_OPTIONS=suppressions="$root/fuzz/lsan.supp" "$build/fuzz/fuzz_$reader" "$corpus" -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$build/artifacts/$reader-" 2>"$build/fuzz_$reader.log" \
    || { tail -40 "$build/fuzz_$reader.log"; echo "fuzz_$reader found a bug: $build/artifacts/" >&2; exit 1; }
  grep -E "stat::number_of_executed_units|stat::new_units_added" "$build/fuzz_$reader.log" | tr '\n' ' '
  echo
done
echo "== fuzzing: no crash in ${#readers[@]} targets x $seconds s; took $((SECONDS - start)) s"

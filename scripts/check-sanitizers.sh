#!/usr/bin/env bash
# `make check-sanitizers` (called by .ci/run after `make test`): the fast unit tests under
# ASan+UBSan, the threaded tests under TSan, and each libFuzzer target for FUZZ_SECONDS.
# Builds with clang in build-asan/ and build-tsan/ (only the targets needed). Any sanitizer
# report fails the check (-fno-sanitize-recover, halt_on_error). docs/robustness.md explains
# the choices; the slow physics tests (minutes under ASan) are left to `make test`.
set -euo pipefail
cd "$(dirname "$0")/.."
JOBS=${JOBS:-$(nproc)}
FUZZ_SECONDS=${FUZZ_SECONDS:-30}
export OMP_WAIT_POLICY=PASSIVE
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
# libomp is not TSan-instrumented; LLVM's Archer (loaded by libomp when it sees TSan) tells
# TSan about OpenMP's barriers and reductions, and the runtime's own accesses are ignored.
export TSAN_OPTIONS=ignore_noninstrumented_modules=1:halt_on_error=1

configure() {  # dir, extra cmake flags...
  local dir=$1; shift
  CC=clang CXX=clang++ cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTIDE_WERROR=OFF \
    -DTIDE_BUILD_EXAMPLES=OFF -DTIDE_BUILD_BENCH=OFF "$@" >/dev/null
}

section() { printf '\n== %s (%s)\n' "$1" "$(date +%T)"; }

# --- ASan + UBSan: unit tests (the minute-long physics runs excluded by name) ---
asan_tests=(test_kernels test_pair_sums test_neighbors test_world test_emitter test_fluid_api test_checkpoint test_exporters
            test_surface_mesh test_far_field_mesh test_wave_theory test_viscosity test_periodic test_ocean_spectrum test_ocean_kinematics
            test_ocean_defs test_stokes_wave test_exact_sum test_partition test_domain_split)
asan_skip="Emitter.FluidJetHasNoGapsOrDoubleLayers:FluidApi.SeedFreeFallBlockRunsVerbatim"
asan_skip+=":PeriodicWorld.FlowCrossesTheSeamsAndConservesParticles:Checkpoint.PcisphAndWcsphResumeBitIdentically"
asan_skip+=":DivergenceGuard.ASaneDamBreakNeverTrips"
section "ASan+UBSan build"
configure build-asan -DTIDE_SANITIZE=address,undefined -DTIDE_FUZZ=ON
cmake --build build-asan -j "$JOBS" --target "${asan_tests[@]}" fuzz_scene_parser fuzz_checkpoint checkpoint_seed
for t in "${asan_tests[@]}"; do
  section "ASan+UBSan $t"
  build-asan/bin/$t --gtest_brief=1 --gtest_filter="-$asan_skip"
done

# --- libFuzzer: the scene parser and the checkpoint loader (ASan+UBSan too) ---
corpus=build-asan/fuzz-corpus
rm -rf "$corpus" && mkdir -p "$corpus/scene" "$corpus/checkpoint" build-asan/fuzz-crashes
cp scenes/*.json "$corpus/scene/"
cp fuzz/regressions/scene/* "$corpus/scene/" 2>/dev/null || true
build-asan/bin/checkpoint_seed "$corpus/checkpoint"
cp fuzz/regressions/checkpoint/* "$corpus/checkpoint/" 2>/dev/null || true
for target in scene_parser:scene checkpoint:checkpoint; do
  name=${target%%:*}; dir=${target##*:}
  section "fuzz_$name for ${FUZZ_SECONDS} s"
  # A unit over -timeout s is a hang and fails; libFuzzer also saves units over
  # -report_slow_units s as slow-unit-* (e.g. a restored state with every particle in one cell:
  # N² neighbours through every pressure iteration, seconds under ASan, finite), which are
  # listed but are not findings.
  build-asan/bin/fuzz_$name -max_total_time="$FUZZ_SECONDS" -max_len=65536 -rss_limit_mb=2048 -print_final_stats=1 \
    -timeout=120 -report_slow_units=30 \
    -artifact_prefix=build-asan/fuzz-crashes/"$name"- "$corpus/$dir" 2>&1 | grep -E '^(stat::|Done|==|SUMMARY)|ERROR' || true
  for slow in build-asan/fuzz-crashes/"$name"-slow-unit-*; do
    if [ -e "$slow" ]; then echo "fuzz_$name: slow unit (not a finding): $slow"; fi
  done
  if ls build-asan/fuzz-crashes/"$name"-* 2>/dev/null | grep -qv -- '-slow-unit-'; then
    echo "fuzz_$name found a crash: build-asan/fuzz-crashes/ (add it to fuzz/regressions/$dir/ once fixed)" >&2
    exit 1
  fi
done

# --- TSan: the threaded tests, two threads on more than kParallelGrain particles ---
section "TSan build"
configure build-tsan -DTIDE_SANITIZE=thread
cmake --build build-tsan -j "$JOBS" --target test_checkpoint
section "TSan sees OpenMP races (self-check)"
# A blind TSan would pass anything: a racy OpenMP sum must be reported, its fixed form not.
cat > build-tsan/omp_race.cpp <<'CPP'
#include <cstdio>
int main(int argc, char**) {
    double sum = 0, a[20000];
    for (double& x : a) x = argc;
#pragma omp parallel for num_threads(2) reduction(+ : sum)
    for (int i = 0; i < 20000; ++i) sum += a[i];
#ifdef RACE
#pragma omp parallel for num_threads(2)
    for (int i = 0; i < 20000; ++i) sum += a[i];
#endif
    std::printf("%g\n", sum);
}
CPP
clang++ -fopenmp -fsanitize=thread -g -O1 build-tsan/omp_race.cpp -o build-tsan/omp_clean
clang++ -fopenmp -fsanitize=thread -g -O1 -DRACE build-tsan/omp_race.cpp -o build-tsan/omp_race
build-tsan/omp_clean >/dev/null
if build-tsan/omp_race >/dev/null 2>build-tsan/omp_race.log || ! grep -q "data race" build-tsan/omp_race.log; then
  echo "TSan did not report the deliberate OpenMP race: the TSan check would be blind" >&2
  exit 1
fi
echo "the deliberate race is reported, the reduction is not"
section "TSan test_checkpoint (2 threads)"
build-tsan/bin/test_checkpoint --gtest_brief=1 \
  --gtest_filter='Checkpoint.DfsphDamBreakResumesBitIdentically:Checkpoint.EmitterAndWaveMakerResumeBitIdentically'
section "sanitizers and fuzzers: no findings"

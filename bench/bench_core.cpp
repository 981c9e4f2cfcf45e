// Google Benchmark: neighbour search and every solver on dam breaks of ~50k and ~200k
// particles. Counters: particle-steps per second (items/s), simulated s per wall s, dt, iterations.
#include <chrono>
#include <cmath>

#include <benchmark/benchmark.h>

#include <tide/world.hpp>

#include "neighbors/neighbor_list.hpp"
#include "neighbors/uniform_grid.hpp"
#include "solvers/pair_kernels.hpp"
#include "solvers/pair_sums.hpp"
#include "testing/scenarios.hpp"

namespace {

/// Spacing that gives the asked number of particles in the dam-break column (0.4³ m³).
float spacingFor(int particles) { return 0.4f / std::cbrt(static_cast<float>(particles)); }

void BM_NeighborSearch(benchmark::State& state) {
    tide::World world = tide::scenarios::damBreak(spacingFor(static_cast<int>(state.range(0))));
    world.step(1.0);  // settle the first reorder
    const auto& x = world.particles().position;
    const float h = world.supportRadius();
    tide::UniformGrid grid;
    tide::NeighborList list;
    for (auto _ : state) {
        grid.build(x, h, world.threads());
        list.build(grid, x, h, world.threads());
        benchmark::DoNotOptimize(list.pairCount());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(x.size()));
    state.counters["particles"] = static_cast<double>(x.size());
    state.counters["neighbours"] = static_cast<double>(list.pairCount()) / static_cast<double>(x.size());
    state.counters["threads"] = world.threads();
}

/// The uniform grid's counting sort alone (the first part of BM_NeighborSearch), at the
/// world's thread count.
void BM_GridBuild(benchmark::State& state) {
    tide::World world = tide::scenarios::damBreak(spacingFor(static_cast<int>(state.range(0))));
    world.step(1.0);
    const auto& x = world.particles().position;
    tide::UniformGrid grid;
    for (auto _ : state) {
        grid.build(x, world.supportRadius(), world.threads());
        benchmark::DoNotOptimize(grid.cellCount());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(x.size()));
    state.counters["cells"] = grid.cellCount();
    state.counters["threads"] = world.threads();
}

/// The pressure solves' pair sums (solvers/pair_sums.hpp) over every particle of the 50k dam
/// break's column after one step, one thread: ns per pair, in SIMD lanes (arg 0) or one pair
/// at a time (arg 1). Which sum: 0 kernel (density), 1 gradient (pressure), 2 divergence.
void BM_PairSums(benchmark::State& state) {
    tide::World world = tide::scenarios::damBreak(spacingFor(50000));
    world.step(1.0);
    const auto& x = world.particles().position;
    const auto& v = world.particles().velocity;
    const float h = world.supportRadius();
    const tide::kernels::SmoothingKernel w(h);
    tide::UniformGrid grid;
    tide::NeighborList list;
    grid.build(x, h, 1);
    list.build(grid, x, h, 1);
    tide::PairKernels factors;
    factors.resize(list, w);
    std::vector<glm::vec4> points(x.size()), velocities(x.size());
    for (std::uint32_t i = 0; i < x.size(); ++i) {
        points[i] = glm::vec4(x[i], 1.0f);
        velocities[i] = glm::vec4(v[i], 0.0f);
        auto codes = factors.of(list, i);
        const auto neighbors = list.of(i);
        for (std::size_t k = 0; k < neighbors.size(); ++k) codes[k] = factors.encode(w, glm::length(x[i] - x[neighbors[k]]));
    }
    const auto order = state.range(0) == 0 ? tide::pair_sums::Order::Lanes : tide::pair_sums::Order::Sequential;
    const auto sum = state.range(1);
    const tide::PeriodicBox box;
    float total = 0.0f;
    for (auto _ : state) {
        for (std::uint32_t i = 0; i < x.size(); ++i) {
            const auto neighbors = list.of(i);
            const tide::pair_sums::Neighbors pairs(neighbors, factors.of(list, i).data());
            if (sum == 0) total += tide::pair_sums::kernelSum(pairs, points.data(), x[i], w, box, 0.0f, order);
            else if (sum == 1) total += tide::pair_sums::gradientSum(pairs, points.data(), x[i], box, order).x;
            else total += tide::pair_sums::divergenceSum(pairs, points.data(), velocities.data(), x[i], v[i], box, order);
        }
    }
    benchmark::DoNotOptimize(total);
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(list.pairCount()));
    state.counters["ns_per_pair"] = benchmark::Counter(static_cast<double>(state.iterations() * list.pairCount()),
                                                       benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.SetLabel(state.range(0) == 0 ? tide::pair_sums::instructionSet() : "sequential");
}

/// The first kSteps steps of a dam break after release, per solver: particle-steps per
/// second, simulated seconds per wall second, mean dt and pressure iterations per step. (Early
/// steps: the flow is still slow, so the CFL steps are near max_dt for the incompressible
/// solvers; wcsph's are set by the speed of sound throughout.)
template <const char* Solver>
void BM_DamBreak(benchmark::State& state) {
    constexpr int kSteps = 10;
    tide::World world = tide::scenarios::damBreak(spacingFor(static_cast<int>(state.range(0))), 0, 1.6f, 0.4f, 0.4f,
                                                  tide::WorldDef{}.reorderInterval, Solver);
    world.step(1.0);
    double wall = 0.0, simulated = 0.0;
    std::uint64_t iterations = 0, steps = 0;
    for (auto _ : state) {
        const auto start = std::chrono::steady_clock::now();
        const std::uint64_t iterationsBefore = world.stats().pressureIterationsSum;
        for (int k = 0; k < kSteps; ++k) simulated += world.step(1.0);
        wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        iterations += world.stats().pressureIterationsSum - iterationsBefore;
        steps += kSteps;
    }
    const double n = world.particles().size();
    state.SetItemsProcessed(static_cast<std::int64_t>(steps) * static_cast<std::int64_t>(n));
    state.counters["particles"] = n;
    state.counters["particle_steps_per_s"] = static_cast<double>(steps) * n / wall;
    state.counters["sim_s_per_wall_s"] = simulated / wall;
    state.counters["mean_dt_ms"] = 1e3 * simulated / static_cast<double>(steps);
    state.counters["iterations_per_step"] = static_cast<double>(iterations) / static_cast<double>(steps);
    state.counters["threads"] = world.threads();
}

constexpr char kClassic[] = "classic";
constexpr char kWcsph[] = "wcsph";
constexpr char kPcisph[] = "pcisph";
constexpr char kDfsph[] = "dfsph";

BENCHMARK(BM_PairSums)->ArgsProduct({{0, 1}, {0, 1, 2}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GridBuild)->Arg(50000)->Arg(200000)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(BM_NeighborSearch)->Arg(50000)->Arg(200000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DamBreak<kClassic>)->Name("BM_DamBreak/classic")->Arg(50000)->Arg(200000)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(BM_DamBreak<kWcsph>)->Name("BM_DamBreak/wcsph")->Arg(50000)->Arg(200000)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(BM_DamBreak<kPcisph>)->Name("BM_DamBreak/pcisph")->Arg(50000)->Arg(200000)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(BM_DamBreak<kDfsph>)->Name("BM_DamBreak/dfsph")->Arg(50000)->Arg(200000)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();

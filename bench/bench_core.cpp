// Google Benchmark: neighbour search and one classic-solver step on dam breaks of ~50k and
// ~200k particles. Counters: particle-steps per second (items/s) and particles.
#include <cmath>

#include <benchmark/benchmark.h>

#include <tide/world.hpp>

#include "neighbors/neighbor_list.hpp"
#include "neighbors/uniform_grid.hpp"
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

/// One step of a solver on the dam break (the column has just been released).
template <const char* Solver>
void BM_Step(benchmark::State& state) {
    tide::World world = tide::scenarios::damBreak(spacingFor(static_cast<int>(state.range(0))), 0, 1.6f, 0.4f, 0.4f,
                                                  tide::WorldDef{}.reorderInterval, Solver);
    world.step(1.0);
    for (auto _ : state) benchmark::DoNotOptimize(world.step(1.0));
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(world.particles().size()));
    state.counters["particles"] = world.particles().size();
    state.counters["dt_ms"] = 1e3 * world.stats().lastDt;
    state.counters["iterations"] = world.stats().lastPressureIterations;
    state.counters["threads"] = world.threads();
}

constexpr char kClassic[] = "classic";
constexpr char kWcsph[] = "wcsph";
constexpr char kPcisph[] = "pcisph";
constexpr char kDfsph[] = "dfsph";

BENCHMARK(BM_NeighborSearch)->Arg(50000)->Arg(200000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Step<kClassic>)->Name("BM_ClassicStep")->Arg(50000)->Arg(200000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Step<kWcsph>)->Name("BM_WcsphStep")->Arg(50000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Step<kPcisph>)->Name("BM_PcisphStep")->Arg(50000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Step<kDfsph>)->Name("BM_DfsphStep")->Arg(50000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();

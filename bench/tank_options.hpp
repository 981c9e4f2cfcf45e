#pragma once
/// \file
/// Command-line options shared by the diagnostic tools on a tank of still water
/// (tide_standing_wave, tide_rest_layers, tide_progressive_wave; the kernel and filter flags also
/// tide_wave_bench and tide_solitary_wave): the tank, the resolution and the solver settings,
/// and the WorldDef they make.

#include <cstdint>
#include <map>
#include <string>

#include <CLI/CLI.hpp>

#include <tide/defs.hpp>

#include "testing/scenarios.hpp"

namespace tide::bench {

/// `--kernel NAME` into `kernel` (solver.kernel's scene names).
inline CLI::Option* addKernelOption(CLI::App& app, KernelShape& kernel) {
    return app.add_option("--kernel", kernel, "solver.kernel")
        ->transform(CLI::CheckedTransformer(std::map<std::string, KernelShape>{{"cubic_spline", KernelShape::CubicSpline},
                                                                               {"wendland_c2", KernelShape::WendlandC2},
                                                                               {"automatic", KernelShape::Automatic}}))
        ->default_str("automatic (Wendland C2 in 2D, cubic spline in 3D)");
}

/// `--smooth-density-error` / `--no-smooth-density-error` set solver.smoothDensityError;
/// neither leaves it automatic (the wave settings decide).
inline void addSmoothDensityErrorFlags(CLI::App& app, SolverDef& solver) {
    app.add_flag_function(
        "--smooth-density-error,!--no-smooth-density-error", [&solver](std::int64_t count) { solver.smoothDensityError = count > 0; },
        "solver.smooth_density_error (dfsph; default: the wave settings', on in 2D for trains of waves)");
}

struct TankOptions {
    std::string solver = "dfsph";
    std::string viscosity;  ///< solver.viscosity; empty: the solver's own
    float spacing = 0.02f, supportRatio = WorldDef{}.supportRatio;
    float length = 0.68f, depth = 0.3f;
    float maxDensityError = SolverDef{}.maxDensityError, xsph = -1.0f, momentum = -1.0f, shifting = 0.0f, differenceForm = 0.0f;
    float maxDivergenceError = SolverDef{}.maxDivergenceError;
    int minIterations = SolverDef{}.minIterations;
    int minDivergenceIterations = SolverDef{}.minDivergenceIterations;
    bool smoothDensityError = false;  ///< a tank has no wave maker: off, as the solver's default
    float divergenceWarmStart = SolverDef{}.divergenceWarmStart;
    float maxDt = SolverDef{}.maxDt, cfl = SolverDef{}.cflNumber;
    int width = 0;  ///< periodic z cell in spacings; 0: the narrowest the support allows
    int maxIterations = SolverDef{}.maxIterations;
    int threads = 1;
    int dimensions = 3;  ///< WorldDef::dimensions: 2 is the plane z = 0 (width then unused)
    KernelShape kernel = SolverDef{}.kernel;

    void addTo(CLI::App& app) {
        app.add_option("--solver", solver, "solver.method")->capture_default_str();
        app.add_option("--viscosity", viscosity, "solver.viscosity (empty: the solver's own; xsph with --xsph 0: none)");
        app.add_option("--spacing", spacing, "particle spacing, m")->capture_default_str()->check(CLI::PositiveNumber);
        addKernelOption(app, kernel);
        app.add_option("--support-ratio", supportRatio, "kernel support / spacing (default: the kernel's own, 2 cubic spline, 3 Wendland C2)")
            ->check(CLI::Range(1.0, 4.0));
        app.add_option("--length", length, "tank length (x), m")->capture_default_str()->check(CLI::PositiveNumber);
        app.add_option("--depth", depth, "water depth, m")->capture_default_str()->check(CLI::PositiveNumber);
        app.add_option("--width", width, "periodic z cell in spacings (0: the narrowest the support allows, at least 4)");
        app.add_option("--max-density-error", maxDensityError, "solver.max_density_error")->capture_default_str();
        app.add_option("--max-divergence-error", maxDivergenceError, "solver.max_divergence_error (negative: max_density_error)")
            ->capture_default_str();
        app.add_option("--min-iterations", minIterations, "solver.min_iterations")->capture_default_str()->check(CLI::NonNegativeNumber);
        app.add_option("--min-divergence-iterations", minDivergenceIterations,
                       "solver.min_divergence_iterations (negative: min_iterations)")
            ->capture_default_str();
        app.add_option("--divergence-warm-start", divergenceWarmStart, "solver.divergence_warm_start")
            ->capture_default_str()
            ->check(CLI::Range(0.0, 1.0));
        app.add_flag("--smooth-density-error", smoothDensityError, "solver.smooth_density_error (dfsph)");
        app.add_option("--xsph", xsph, "solver.xsph (negative: the solver's default)")->capture_default_str();
        app.add_option("--momentum", momentum, "solver.momentum (negative: the solver's default)")->capture_default_str();
        app.add_option("--shifting", shifting, "solver.shifting (dfsph: Fickian particle shifting, 0 off)")
            ->capture_default_str()
            ->check(CLI::Range(0.0, 1.0));
        app.add_option("--difference-form", differenceForm,
                       "solver.difference_form (dfsph: share of the smoothed pressure's self-term in the difference form, 0 off)")
            ->capture_default_str()
            ->check(CLI::Range(0.0, 1.0));
        app.add_option("--max-iterations", maxIterations, "solver.max_iterations")->capture_default_str()->check(CLI::PositiveNumber);
        app.add_option("--max-dt", maxDt, "solver.max_dt, s")->capture_default_str()->check(CLI::PositiveNumber);
        app.add_option("--cfl", cfl, "solver.cfl")->capture_default_str()->check(CLI::PositiveNumber);
        app.add_option("--threads", threads, "worker threads")->capture_default_str();
        app.add_option("--dimensions", dimensions, "2: a true 2D world (the plane z = 0); 3: a periodic z slab")
            ->capture_default_str()
            ->check(CLI::IsMember({2, 3}));
    }
    [[nodiscard]] int widthInSpacings() const {
        return width > 0 ? width : scenarios::periodicWidthInSpacings(withResolvedKernel(worldDef()).supportRatio);
    }
    [[nodiscard]] WorldDef worldDef() const {
        WorldDef def;
        def.particleSpacing = spacing;
        def.supportRatio = supportRatio;
        def.threads = threads;
        def.dimensions = dimensions;
        def.solver.method = solver;
        def.solver.kernel = kernel;
        def.solver.viscosity = viscosity;
        def.solver.maxDensityError = maxDensityError;
        def.solver.xsph = xsph;
        def.solver.momentum = momentum;
        def.solver.shifting = shifting;
        def.solver.differenceForm = differenceForm;
        def.solver.maxIterations = maxIterations;
        def.solver.maxDivergenceError = maxDivergenceError;
        def.solver.minIterations = minIterations;
        def.solver.minDivergenceIterations = minDivergenceIterations;
        def.solver.divergenceWarmStart = divergenceWarmStart;
        def.solver.smoothDensityError = smoothDensityError;
        def.solver.maxDt = maxDt;
        def.solver.cflNumber = cfl;
        return def;
    }
};

}  // namespace tide::bench

// What sets the time step: runs a scene on one thread and reports, per output frame, which
// limit each step took (the CFL speed limit, solver.max_dt, or landing on the frame time),
// the speed distribution (max, 99.9th and 99th percentiles; particles faster than a given
// speed) and where the fastest particle is (its distance to the nearest wall of the domain
// box and how many walls lie within one kernel support: 1 a wall, 2 an edge, 3 a corner).
//
//   tide_dt_report SCENE [--seconds S] [--fast V] [--steps]
//
// Energy: E/E0 is the fluid's kinetic plus potential energy (from the domain floor) over its
// value at the start, which an incompressible fluid in fixed walls can only lose; e_max/gH
// is the largest specific energy ½|v|² + g·height of one particle over g times the highest
// starting particle's height: above 1, pressure work has concentrated energy into it.
//
// --fast V counts particles above V m/s (default 2√(g·1 m) = 6.26 m/s, the front speed of
// Ritter's dam-break solution for a 1 m column); --steps prints one line per step as well.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <tide/io/scene.hpp>
#include <tide/world.hpp>

namespace {

struct Totals {
    long steps = 0;
    double seconds = 0.0;
};

float percentile(std::vector<float>& values, double q) {
    const auto k = static_cast<std::size_t>(q * static_cast<double>(values.size() - 1));
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
    return values[k];
}

}  // namespace

int main(int argc, char** argv) try {
    if (argc < 2) {
        std::fprintf(stderr, "usage: tide_dt_report SCENE [--seconds S] [--fast V] [--steps]\n");
        return 2;
    }
    double seconds = -1.0;
    float fast = 2.0f * std::sqrt(9.81f);
    bool perStep = false;
    for (int a = 2; a < argc; ++a) {
        const std::string arg = argv[a];
        if (arg == "--seconds" && a + 1 < argc) seconds = std::atof(argv[++a]);
        else if (arg == "--fast" && a + 1 < argc) fast = static_cast<float>(std::atof(argv[++a]));
        else if (arg == "--steps") perStep = true;
        else {
            std::fprintf(stderr, "tide_dt_report: unknown argument %s\n", arg.c_str());
            return 2;
        }
    }
    tide::io::Scene scene = tide::io::loadScene(argv[1]);
    if (seconds < 0.0) seconds = scene.endTime;
    scene.world.threads = 1;
    tide::World world = tide::io::buildWorld(scene);
    const tide::WorldDef& def = world.def();
    const double maxDt = def.solver.maxDt;
    const float support = world.supportRadius();
    const double frameLength = 1.0 / scene.output.fps;
    const glm::vec3 g = def.gravity;
    // Energy of the fluid: ½ m |v|² + m g·(floor − x) with the floor at domainMin along g.
    auto specific = [&](const glm::vec3& x, const glm::vec3& v) {
        return 0.5f * glm::dot(v, v) - glm::dot(g, x - def.domainMin);
    };
    auto energy = [&] {
        const tide::ParticleStore& p = world.particles();
        double e = 0.0;
        for (std::uint32_t i = 0; i < p.size(); ++i) e += p.mass[i] * specific(p.position[i], p.velocity[i]);
        return e;
    };
    const double energy0 = energy();
    float top = 0.0f;
    for (const glm::vec3& x : world.particles().position) top = std::max(top, specific(x, glm::vec3(0.0f)));

    Totals cfl, max, landing;
    std::vector<float> speeds;
    std::printf("# frame end | steps, mean dt ms | steps at CFL / max_dt / landing | max |v|, p99.9, p99 m/s, "
                "n > %.2f m/s | fastest at (x y z), wall distance m, walls within h | E/E0, e_max/gH\n", fast);
    int frame = 0;
    while (world.time() < seconds - 1e-9) {
        const double target = std::min((frame + 1) * frameLength, seconds);
        const double frameStart = world.time();
        Totals fCfl, fMax, fLanding;
        float fVmax = 0.0f, fP999 = 0.0f, fP99 = 0.0f;
        int fFast = 0, fWalls = 0;
        float fWall = 0.0f, fSpecific = 0.0f;
        glm::vec3 fAt(0.0f);
        double before = world.time();
        world.advance(target - world.time(), [&] {
            const tide::ParticleStore& p = world.particles();
            const double dt = world.stats().lastDt;
            const double remaining = target - before;
            before = world.time();
            // landOn(): the step is the time left to the frame, or half of it.
            const bool lands = std::abs(dt - remaining) <= 1e-12 * target || std::abs(dt - 0.5 * remaining) <= 1e-12 * target;
            Totals& kind = std::abs(dt - maxDt) <= 1e-9 ? fMax : lands ? fLanding : fCfl;
            ++kind.steps;
            kind.seconds += dt;
            speeds.resize(p.size());
            std::uint32_t fastest = 0;
            int above = 0;
            for (std::uint32_t i = 0; i < p.size(); ++i) {
                speeds[i] = std::sqrt(glm::dot(p.velocity[i], p.velocity[i]));
                if (speeds[i] > speeds[fastest]) fastest = i;
                above += speeds[i] > fast;
            }
            const float vmax = speeds[fastest];
            const glm::vec3 x = p.position[fastest];
            const glm::vec3 lo = x - def.domainMin, hi = def.domainMax - x;
            const float wall = std::min({lo.x, lo.y, lo.z, hi.x, hi.y, hi.z});
            int walls = 0;
            for (int a = 0; a < 3; ++a) walls += (lo[a] < support || hi[a] < support) ? 1 : 0;
            for (std::uint32_t i = 0; i < p.size(); ++i) fSpecific = std::max(fSpecific, specific(p.position[i], p.velocity[i]));
            const float p999 = percentile(speeds, 0.999), p99 = percentile(speeds, 0.99);
            if (perStep)
                std::printf("  t %.5f dt %.4f ms %s |v| %.3f p99.9 %.3f p99 %.3f n>%.2f %d at (%.3f %.3f %.3f) wall %.4f walls %d\n",
                            world.time(), 1e3 * dt, &kind == &fMax ? "max_dt" : &kind == &fLanding ? "landing" : "cfl", vmax,
                            p999, p99, fast, above, x.x, x.y, x.z, wall, walls);
            if (vmax >= fVmax) {
                fVmax = vmax;
                fAt = x;
                fWall = wall;
                fWalls = walls;
            }
            fP999 = std::max(fP999, p999);
            fP99 = std::max(fP99, p99);
            fFast = std::max(fFast, above);
        });
        const long steps = fCfl.steps + fMax.steps + fLanding.steps;
        std::printf("%.3f | %ld, %.3f | %ld / %ld / %ld | %.2f, %.2f, %.2f, %d | (%.3f %.3f %.3f), %.4f, %d | %.3f, %.2f\n",
                    world.time(), steps, 1e3 * (world.time() - frameStart) / static_cast<double>(std::max(steps, 1L)), fCfl.steps,
                    fMax.steps, fLanding.steps, fVmax, fP999, fP99, fFast, fAt.x, fAt.y, fAt.z, fWall, fWalls,
                    energy() / energy0, top > 0.0f ? fSpecific / top : 0.0f);
        std::fflush(stdout);
        for (auto [total, part] : {std::pair{&cfl, &fCfl}, std::pair{&max, &fMax}, std::pair{&landing, &fLanding}}) {
            total->steps += part->steps;
            total->seconds += part->seconds;
        }
        ++frame;
    }
    const tide::WorldStats& st = world.stats();
    std::printf("total: %lu steps, mean dt %.3f ms, %.2f iterations/step, max mean compression %.4f %%; "
                "CFL %ld steps (%.3f s), max_dt %ld (%.3f s), landing %ld (%.3f s)\n",
                static_cast<unsigned long>(st.steps), 1e3 * st.dtSum / static_cast<double>(std::max<std::uint64_t>(st.steps, 1)),
                static_cast<double>(st.pressureIterationsSum) / static_cast<double>(std::max<std::uint64_t>(st.steps, 1)),
                100.0 * st.maxMeanCompression, cfl.steps, cfl.seconds, max.steps, max.seconds, landing.steps, landing.seconds);
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "tide_dt_report: %s\n", e.what());
    return 1;
}

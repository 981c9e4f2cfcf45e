// Divergence::describe: the one line a user reads when a run stops.
#include <tide/world.hpp>

#include <algorithm>
#include <cstdint>
#include <sstream>

namespace tide {

std::string Divergence::describe() const {
    std::ostringstream out;
    out << "step " << step << " (t = " << time << " s, dt = " << dt << " s): ";
    const auto particleText = [&] {
        std::ostringstream p;
        p << "particle " << particle << " (id " << id << ")";
        return p.str();
    };
    switch (quantity) {
        case DivergedQuantity::Position: out << particleText() << " has a non-finite position (" << value << ")"; break;
        case DivergedQuantity::Velocity: out << particleText() << " has a non-finite velocity (" << value << ")"; break;
        case DivergedQuantity::Density: out << particleText() << " has a non-finite density (" << value << ")"; break;
        case DivergedQuantity::Pressure: out << particleText() << " has a non-finite pressure (" << value << ")"; break;
        case DivergedQuantity::Speed:
            out << particleText() << " has a runaway speed of " << value << " m/s, above " << limit
                << " m/s (it would cross " << kRunawaySupports << " kernel supports in one step)";
            break;
        case DivergedQuantity::Compression:
            out << "the fluid collapsed (mean compression " << 100.0f * limit << " %, above "
                << 100.0f * kCollapsedCompression << " %): " << particleText() << " has density " << value << " kg/m3";
            break;
    }
    if (unconvergedOfLast32 > 0)
        out << "; before it, the pressure solve stopped short of its density tolerance in " << unconvergedOfLast32
            << " of the last " << std::min<std::uint64_t>(step, 32) << " steps (solver.max_iterations " << maxIterations
            << "): raise solver.max_iterations, shorten solver.max_dt, or (dfsph) keep solver.momentum on";
    if (solver == "dfsph" && densityRatio >= kFarApartDensities)
        out << "; the rest densities are " << densityRatio
            << ":1 apart, which dfsph may not hold in thin boxes or thin layers: solver.method \"pcisph\" does";
    return out.str();
}

}  // namespace tide

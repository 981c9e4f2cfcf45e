#include <stdexcept>

#include <tide/world.hpp>

#include "solvers/classic_muller2003.hpp"
#include "solvers/dfsph_bender2017.hpp"
#include "solvers/pbf_macklin2013.hpp"
#include "solvers/pcisph_solenthaler2009.hpp"
#include "solvers/wcsph_becker2007.hpp"
#include "solvers/solver.hpp"

namespace tide {

namespace {
struct Entry {
    std::string_view name;
    std::unique_ptr<Solver> (*make)();
};
constexpr Entry kSolvers[] = {
    {"classic", []() -> std::unique_ptr<Solver> { return std::make_unique<ClassicMuller2003>(); }},
    {"wcsph", []() -> std::unique_ptr<Solver> { return std::make_unique<WcsphBecker2007>(); }},
    {"pcisph", []() -> std::unique_ptr<Solver> { return std::make_unique<PcisphSolenthaler2009>(); }},
    {"dfsph", []() -> std::unique_ptr<Solver> { return std::make_unique<DfsphBender2017>(); }},
    {"pbf", []() -> std::unique_ptr<Solver> { return std::make_unique<PbfMacklin2013>(); }},
};
}  // namespace

std::vector<std::string> solverNames() {
    std::vector<std::string> names;
    for (const auto& entry : kSolvers) names.emplace_back(entry.name);
    return names;
}

std::unique_ptr<Solver> makeSolver(std::string_view name) {
    for (const auto& entry : kSolvers)
        if (entry.name == name) return entry.make();
    std::string known;
    for (const auto& entry : kSolvers) known += (known.empty() ? "" : ", ") + std::string(entry.name);
    throw std::invalid_argument("solver.method: unknown solver \"" + std::string(name) + "\" (known: " + known + ")");
}

}  // namespace tide

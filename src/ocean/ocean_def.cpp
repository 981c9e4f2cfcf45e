// Validation of the ocean's definition structs (include/tide/ocean.hpp).
#include <tide/ocean.hpp>

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "ocean/dispersion.hpp"
#include "ocean/spectrum.hpp"
#include "ocean/stokes_wave_fenton1985.hpp"

namespace tide {

namespace {

template <class T>
[[noreturn]] void refuse(const std::string& field, const std::string& what, T value) {
    std::ostringstream message;
    message << field << ": " << what << ", got " << value;
    throw std::invalid_argument(message.str());
}

void requirePositive(const std::string& field, double v) {
    if (!(v > 0.0) || !std::isfinite(v)) refuse(field, "must be > 0", v);
}

void requireInRange(const std::string& field, double v, double lo, double hi) {
    if (!(v >= lo && v <= hi)) {
        std::ostringstream what;
        what << "must be in [" << lo << ", " << hi << "]";
        refuse(field, what.str(), v);
    }
}

void validateWaves(const OceanWavesDef& w, double depth) {
    const std::string path = "ocean.waves.";
    requireInRange(path + "direction", w.direction, -360.0, 360.0);
    if (w.type == OceanWavesDef::Type::Regular) {
        requirePositive(path + "height", w.height);
        requirePositive(path + "period", w.period);
        if (w.spreading) refuse(path + "spreading", "applies to spectra, not to regular waves", *w.spreading);
        if (w.gamma) refuse(path + "gamma", "applies to a jonswap spectrum, not to regular waves", *w.gamma);
        requireInRange(path + "order", w.order, 0, 5);
        // The wave must be one Stokes' theory holds (refuses naming the order).
        if (w.order > 1) (void)ocean::stokesWave(w.height, w.period, depth, ocean::kGravity, w.order, w.meanCurrent, "ocean.waves.order");
        return;
    }
    if (w.order > 1 || w.order < 0) refuse(path + "order", "applies to regular waves (a spectrum is linear: 1)", w.order);
    requirePositive(path + "hs", w.hs);
    requirePositive(path + "tp", w.tp);
    if (w.gamma) {
        if (w.type == OceanWavesDef::Type::PiersonMoskowitz)
            refuse(path + "gamma", "applies to a jonswap spectrum (pierson_moskowitz has gamma 1)", *w.gamma);
        requireInRange(path + "gamma", *w.gamma, 1.0, 7.0);
    }
    if (w.spreading) {
        if (!(*w.spreading > 0.0 && *w.spreading <= 1000.0))
            refuse(path + "spreading", "must be in (0, 1000]", *w.spreading);
        if (w.directions != 0) requireInRange(path + "directions", w.directions, 1, 360);
    } else if (w.directions > 1 || w.directions < 0) {
        refuse(path + "directions", "must be 0 or 1 for a long-crested sea (no spreading)", w.directions);
    }
    requireInRange(path + "components", w.components, 1, 4096);
}

}  // namespace

void validateOcean(const OceanDef& def) {
    requirePositive("ocean.depth", def.depth);
    validateWaves(def.waves, def.depth);
    if (!(def.zoneWidth >= 0.0) || !std::isfinite(def.zoneWidth))
        refuse("ocean.zone_width", "must be >= 0 (0: one peak wavelength)", def.zoneWidth);
    for (std::size_t i = 0; i < def.openSides.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (def.openSides[i] == def.openSides[j])
                refuse("ocean.open_sides[" + std::to_string(i) + "]", "is listed twice", oceanSideName(def.openSides[i]));
}

namespace ocean {

std::optional<StokesWave> oceanStokesWave(const OceanDef& def, double g) {
    validateOcean(def);
    const OceanWavesDef& w = def.waves;
    if (w.type != OceanWavesDef::Type::Regular || w.order == 1) return std::nullopt;
    if (w.order > 1) return stokesWave(w.height, w.period, def.depth, g, w.order, w.meanCurrent, "ocean.waves.order");
    try {
        return stokesWave(w.height, w.period, def.depth, g, 5, w.meanCurrent);
    } catch (const std::invalid_argument&) {
        return std::nullopt;  // too shallow (or too steep) for Stokes' series: Airy's wave
    }
}

}  // namespace ocean

int oceanWaveOrder(const OceanDef& def, double g) {
    const auto stokes = ocean::oceanStokesWave(def, g);
    return stokes ? stokes->order : 1;
}

double oceanMeanCurrent(const OceanDef& def, double g) {
    const auto stokes = ocean::oceanStokesWave(def, g);
    return stokes ? stokes->current : 0.0;
}

double oceanGamma(const OceanWavesDef& waves) {
    if (waves.type != OceanWavesDef::Type::Jonswap) return 1.0;
    return waves.gamma ? *waves.gamma : ocean::dnvGamma(waves.hs, waves.tp);
}

double oceanPeakWavelength(const OceanDef& def, double g) {
    validateOcean(def);
    const double period = def.waves.type == OceanWavesDef::Type::Regular ? def.waves.period : def.waves.tp;
    const double twoPi = 2.0 * std::numbers::pi;
    if (const auto stokes = ocean::oceanStokesWave(def, g)) return twoPi / stokes->k;
    return twoPi / ocean::waveNumber(twoPi / period, def.depth, g);
}

double oceanZoneWidth(const OceanDef& def, double g) {
    return def.zoneWidth > 0.0 ? def.zoneWidth : oceanPeakWavelength(def, g);
}

double oceanCrestHeight(const OceanDef& def) {
    return def.waves.type == OceanWavesDef::Type::Regular ? def.waves.height : def.waves.hs;
}

std::uint32_t oceanStillWaterLayers(double depth, double spacing) {
    const double n = std::round(depth / spacing);
    return n >= 1.0 ? (n < 4.0e9 ? static_cast<std::uint32_t>(n) : 4000000000u) : 1u;
}

void checkRoomAboveSea(const OceanDef& def, double headroom) {
    const double crest = oceanCrestHeight(def);
    if (headroom < crest - 1e-6) {  // (a domain is in float)
        std::ostringstream message;
        message << "domain.max[1]: the domain's top stands " << headroom
                << " m above the ocean's still water, under its crests (about " << crest << " m: "
                << (def.waves.type == OceanWavesDef::Type::Regular ? "the wave height" : "Hs") << "); raise it by "
                << crest - headroom << " m or more";
        throw std::invalid_argument(message.str());
    }
}

const char* oceanSideName(OceanSide side) {
    switch (side) {
        case OceanSide::MinusX: return "-x";
        case OceanSide::PlusX: return "+x";
        case OceanSide::MinusZ: return "-z";
        case OceanSide::PlusZ: return "+z";
    }
    return "?";
}

}  // namespace tide

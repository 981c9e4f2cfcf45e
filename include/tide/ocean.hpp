#pragma once
/// \file
/// The far-field sea of an ocean scene (scene key `"ocean"`): a still-water depth, a sea state
/// (regular waves or a directional JONSWAP / Pierson–Moskowitz spectrum) and the near field's
/// coupling zones. Plain definition structs, validated by tide::validateOcean (and whenever a
/// sea is made from them). Lengths in m, periods in s, directions in degrees from +x towards +z
/// (tide is y-up: the sea surface is the x–z plane, still water at y = 0).

#include <cstdint>
#include <optional>
#include <vector>

namespace tide {

/// The sea state of an ocean (scene key `ocean.waves`).
struct OceanWavesDef {
    enum class Type {
        Regular,           ///< one sinusoid: `height`, `period`
        Jonswap,           ///< JONSWAP spectrum (Hasselmann et al. 1973): `hs`, `tp`, `gamma`
        PiersonMoskowitz,  ///< Pierson & Moskowitz 1964: `hs`, `tp` (JONSWAP with γ = 1)
    };
    Type type = Type::Jonswap;
    double height = 0.0;  ///< regular: H, crest to trough, m
    double period = 0.0;  ///< regular: T, s
    /// Regular waves: the order of Stokes' theory, 1 (Airy: one sinusoid, a = H/2) to 5
    /// (Fenton 1985: the wave of height H crest to trough with its bound harmonics and its
    /// amplitude dispersion, no mean current); 0 picks 5 where its series converges, else 1
    /// (oceanWaveOrder). Spectra: 0 or 1 (a linear sea).
    int order = 0;
    /// Regular waves of order 3 and up: the mean current under them (Fenton 1985's two
    /// definitions). None: no mean Eulerian current, the water drifts with the waves (the open
    /// sea). Return: no mass flux, a uniform current against the waves carries their Stokes
    /// drift back (a closed flume's waves).
    enum class MeanCurrent { None, Return };
    MeanCurrent meanCurrent = MeanCurrent::None;
    double hs = 0.0;      ///< spectra: significant wave height Hm0 = 4 √m0, m
    double tp = 0.0;      ///< spectra: peak period, s
    /// Mean direction the waves travel towards, degrees from +x towards +z, in [−360, 360].
    double direction = 0.0;
    /// s of the cos-2s spreading D(θ) ∝ cos^{2s}((θ − θ̄)/2) (Longuet-Higgins et al. 1963), in
    /// (0, 1000]; larger is narrower (wind sea ~10, swell ~75, Goda 2000, ch. 2). None: long-crested.
    std::optional<double> spreading;
    /// JONSWAP peak enhancement γ in [1, 7] (the range of DNV-RP-C205's normalisation A_γ, which
    /// holds Hs within 0.2 % up to γ = 5 and 0.9 % at 7). None:
    /// DNV-RP-C205 (2010) §3.5.5's rule from Tp/√Hs (5 below 3.6, exp(5.75 − 1.15 Tp/√Hs) up to 5, then 1).
    std::optional<double> gamma;
    std::uint64_t seed = 0;  ///< the random phases (the same seed gives the same sea everywhere)
    /// Spectra: frequency bands, in [1, 4096] (regular waves have one component).
    int components = 64;
    /// Spectra with spreading: directions per frequency band, in [1, 360]; 0 picks 16
    /// (1 when long-crested, where it must be 0 or 1).
    int directions = 0;
};

/// A face of the near field that the far field's waves enter and leave through.
enum class OceanSide : std::uint8_t { MinusX, PlusX, MinusZ, PlusZ };

/// An ocean (scene key `ocean`): the far-field sea around the near field (the domain).
/// The sea's own coordinates have still water at y = 0 and the floor at y = −depth; in a scene
/// the floor is the domain's, so sea y = world y − (domain.min.y + depth).
struct OceanDef {
    double depth = 0.0;   ///< still-water depth, m
    OceanWavesDef waves;  ///< the sea state
    /// Width W of the coupling zones along the open sides, m; 0 picks one peak wavelength.
    double zoneWidth = 0.0;
    std::vector<OceanSide> openSides;  ///< the faces open to the far field (the others stay walls)
};

/// Throws std::invalid_argument naming the field and the value (as the scene's JSON path,
/// e.g. "ocean.waves.hs: must be > 0, got -1") if `def` cannot make a sea.
void validateOcean(const OceanDef& def);

/// The order of the sea's waves: `waves.order`, or for 0 (regular waves) 5 where Stokes'
/// fifth-order series converges for the wave (ocean::stokesWave accepts it), else 1; spectra 1.
int oceanWaveOrder(const OceanDef& def, double g = 9.81);

/// The uniform current under a Stokes wave, along its direction (negative: against it), m/s:
/// with MeanCurrent::Return the current that carries its Stokes drift back; otherwise, and
/// for linear seas, 0.
double oceanMeanCurrent(const OceanDef& def, double g = 9.81);

/// The JONSWAP γ a sea uses: `waves.gamma`, or DNV-RP-C205's from Tp/√Hs when it is unset
/// (1 for Pierson–Moskowitz and regular waves).
double oceanGamma(const OceanWavesDef& waves);

/// The wavelength 2π/k at the peak period (regular waves: at the period) on the ocean's depth
/// (ω² = g k tanh kd; a Stokes wave's own k), m. Validates `def` first.
double oceanPeakWavelength(const OceanDef& def, double g = 9.81);

/// The coupling zones' width: `zoneWidth`, or one peak wavelength when it is 0, m.
double oceanZoneWidth(const OceanDef& def, double g = 9.81);

/// How far above still water the sea's crests may reach, m: H for regular waves (a steep or
/// shallow-water wave's crest stands up to ~0.8 H above it), Hs for a spectrum (the highest of
/// a thousand Rayleigh-distributed crests is ~0.93 Hs, √(2 ln N)/4 Hs; Longuet-Higgins 1952).
double oceanCrestHeight(const OceanDef& def);

/// The layers of particles still water `depth` deep is filled with on a lattice of `spacing`
/// (World::fillOcean, and the zones' inflow): the nearest whole number of spacings, at least
/// one, each depth/n tall, their particles' mass scaled by (depth/n)/spacing, so the water
/// stands at the still water level at rest density. Whole cubic cells would leave it up to a
/// spacing low (0.7 m at 16 mm: 43 cells, 12 mm under the far field's still water).
std::uint32_t oceanStillWaterLayers(double depth, double spacing);

/// Throws std::invalid_argument naming domain.max[1] when the domain's top stands less than
/// oceanCrestHeight above still water (`headroom`, m): a lid that clips every crest (an
/// irregular sea under a top 4 cm above its still water lost 40 % of its Hm0 in a wavelength).
/// World::setOcean and the scene reader call it.
void checkRoomAboveSea(const OceanDef& def, double headroom);

/// The scene key of a side: "-x", "+x", "-z", "+z".
const char* oceanSideName(OceanSide side);

}  // namespace tide

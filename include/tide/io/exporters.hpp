#pragma once
/// \file
/// Particle-frame exporters (VTU, PLY, CSV), the fluid's surface mesh (OBJ), ParaView time
/// series (.pvd), and the atomic file writing they all go through.

#include <filesystem>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include <tide/io/surface_mesh.hpp>
#include <tide/particles.hpp>

namespace tide::io {

/// File format of one exported particle frame.
enum class Format {
    Vtu,  ///< VTK XML UnstructuredGrid, raw appended binary data (ParaView, meshio)
    Ply,  ///< binary little-endian PLY point cloud
    Csv,  ///< comma-separated text, one row per particle
    Obj,  ///< Wavefront OBJ: the fluid's surface as triangles, one object per material (surface_mesh.hpp)
};

/// The format named "vtu", "ply", "csv" or "obj" (exact, lowercase); std::nullopt for anything else.
[[nodiscard]] std::optional<Format> parseFormat(std::string_view name);

/// The file extension of a format, without the dot: "vtu", "ply", "csv" or "obj".
[[nodiscard]] std::string_view extension(Format format);

/// Writes a file so that a reader never sees it half-written: `write` fills a temporary
/// file in the same directory (`.<name>.tmp-<pid>-<n>`), which is flushed, fsynced and then
/// renamed over `file`. On any failure (including an exception from `write`) the temporary
/// file is removed, `file` keeps its earlier content, and std::runtime_error is thrown
/// with a message naming the path and the reason.
void writeFileAtomically(const std::filesystem::path& file, const std::function<void(std::ostream&)>& write);

/// Writes one frame of particles to `file` atomically: per particle its position, velocity,
/// density, pressure, material index and id (CSV has no id column: its header is the fixed
/// `x,y,z,vx,vy,vz,density,pressure,material`); for Format::Obj the surface mesh built with
/// `surface` (whose particle spacing it needs). Throws std::runtime_error on failure, and
/// std::invalid_argument if the particle arrays do not all have the same size or (obj) the
/// particle spacing is not positive.
void writeFrame(const std::filesystem::path& file, Format format, const ParticleStore& particles,
                const SurfaceMeshDef& surface = {});

/// Writes a parallel VTU frame (`.pvtu`, VTK XML PUnstructuredGrid) atomically: the arrays a
/// writeFrame VTU piece holds, and `pieces` (file names relative to the .pvtu's folder), one
/// per process of a split run. Throws std::runtime_error on failure.
void writePvtu(const std::filesystem::path& file, const std::vector<std::string>& pieces);

/// A ParaView time series (.pvd collection) of frame files.
class PvdWriter {
public:
    /// A series to be written to `pvdFile`; nothing is written until write().
    explicit PvdWriter(std::filesystem::path pvdFile);

    /// Adds a frame at simulated time `time` (s); `relativeFile` is relative to the .pvd's directory.
    void add(double time, const std::string& relativeFile);

    /// Rewrites the whole .pvd atomically with every frame added so far.
    void write() const;

private:
    struct Entry {
        double time;
        std::string file;
    };
    std::filesystem::path pvdFile_;
    std::vector<Entry> entries_;
};

}  // namespace tide::io

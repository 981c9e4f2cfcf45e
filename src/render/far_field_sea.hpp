#pragma once
// The far field of an ocean scene drawn to the horizon (issue 43): a camera-centred polar mesh
// on the still-water plane, moved and raised by the sea (ocean/sea_surface.hpp: the components
// the coupling zones use, so it meets the near field's water), shaded as deep water and cut
// away over the near field. Rings grow geometrically outwards, so the mesh is fine where the
// camera looks closely and coarse (with the short waves faded out) at the horizon.
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include <tide/render/camera.hpp>
#include <tide/render/snapshot.hpp>

#include "frame.hpp"
#include "gl.hpp"
#include "ocean/sea.hpp"
#include "ocean/sea_surface.hpp"

namespace tide::render {

/// How water is shaded: its colour (linear RGB), absorption (1/m, of the colours it lacks),
/// the fog distance (m), and how far above the water's surface the near field's drawn surface
/// stands (m: the particles' spheres reach past the top layer's centres).
struct WaterLook {
    glm::vec3 color{0.2f, 0.45f, 0.9f};
    float absorption = 1.0f;
    float fogDistance = 100.0f;
    float surfaceLift = 0.0f;
};

class FarFieldSea {
public:
    FarFieldSea();
    ~FarFieldSea();
    FarFieldSea(const FarFieldSea&) = delete;
    FarFieldSea& operator=(const FarFieldSea&) = delete;

    /// Samples the sea of `snapshot` for its time around the camera (nothing without an ocean).
    void update(const Snapshot& snapshot, const Camera& camera);
    /// Draws the mesh into the bound framebuffer, depth tested; `water` is how the near field's
    /// water is shaded, so that the two match. Around the near field, or (`zones`) over its
    /// coupling zones with an alpha from 1 at the open faces to 0 at the zones' inner edges,
    /// to be blended over the particles' shaded surface.
    void draw(const Frame& frame, const Camera& camera, const Snapshot& snapshot, const WaterLook& water,
              bool zones = false) const;
    [[nodiscard]] bool active() const { return sea_ != nullptr; }

private:
    void buildRings(float innerSpacing, float outerRadius);

    gl::Program program_;
    GLuint vertexArray_ = 0, vertexBuffer_ = 0, indexBuffer_ = 0;
    GLsizei indexCount_ = 0;
    std::unique_ptr<ocean::Sea> sea_;
    std::string seaKey_;              // the ocean the sea was made from
    std::vector<glm::dvec2> offsets_; // rest points around the centre
    std::vector<float> spacing_;      // their local mesh spacing, m
    std::vector<glm::dvec2> rest_;
    std::vector<ocean::SurfacePoint> points_;
    glm::vec2 ringsFor_{0.0f};        // (inner spacing, outer radius) the rings were built for
    double sampledTime_ = -1.0;
    glm::dvec2 sampledCentre_{0.0};
};

}  // namespace tide::render

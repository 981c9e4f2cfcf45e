#pragma once
// The viewer's camera: orbits a target point, zooms along its view direction, pans sideways.
#include <tide/render/camera.hpp>

namespace tide::view {

class OrbitCamera {
public:
    /// Start where `camera` looks from.
    explicit OrbitCamera(const render::Camera& camera);

    /// Drag by (dx, dy) pixels: turn around the target.
    void orbit(float dx, float dy);
    /// Move the target (and the eye) with a drag of (dx, dy) pixels in a window `height` tall.
    void pan(float dx, float dy, int height);
    /// Scroll `steps` notches: closer for positive.
    void zoom(float steps);
    [[nodiscard]] render::Camera camera() const;
    /// World length of one pixel at the target's distance, in a window `height` tall.
    [[nodiscard]] float pixelSize(int height) const;

private:
    render::Camera base_;  // fov and clip planes
    glm::vec3 target_;
    float distance_, yaw_, pitch_;
};

}  // namespace tide::view

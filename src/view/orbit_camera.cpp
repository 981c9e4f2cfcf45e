// Orbit / pan / zoom around a target.
#include "orbit_camera.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace tide::view {

OrbitCamera::OrbitCamera(const render::Camera& camera) : base_(camera), target_(camera.target) {
    const glm::vec3 offset = camera.eye - camera.target;
    distance_ = std::max(glm::length(offset), 1e-4f);
    yaw_ = std::atan2(offset.x, offset.z);
    pitch_ = std::asin(std::clamp(offset.y / distance_, -1.0f, 1.0f));
}

void OrbitCamera::orbit(float dx, float dy) {
    yaw_ -= 0.006f * dx;
    pitch_ = std::clamp(pitch_ + 0.006f * dy, -1.5f, 1.5f);  // never straight up: lookAt's up would flip
}

float OrbitCamera::pixelSize(int height) const {
    return 2.0f * distance_ * std::tan(glm::radians(0.5f * base_.fovDegrees)) / static_cast<float>(std::max(height, 1));
}

void OrbitCamera::pan(float dx, float dy, int height) {
    const render::Camera c = camera();
    const glm::vec3 forward = glm::normalize(c.target - c.eye);
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
    const glm::vec3 up = glm::cross(right, forward);
    target_ += (-dx * right + dy * up) * pixelSize(height);
}

void OrbitCamera::zoom(float steps) {
    distance_ = std::clamp(distance_ * std::pow(0.88f, steps), base_.nearPlane * 10.0f, base_.farPlane * 0.2f);
}

render::Camera OrbitCamera::camera() const {
    render::Camera c = base_;
    c.target = target_;
    c.eye = target_ + distance_ * glm::vec3(std::cos(pitch_) * std::sin(yaw_), std::sin(pitch_),
                                            std::cos(pitch_) * std::cos(yaw_));
    return c;
}

}  // namespace tide::view

// Camera matrices and the default view of a container.
#include <tide/render/camera.hpp>

#include <algorithm>
#include <cmath>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace tide::render {

Camera fitClipPlanes(Camera camera, const glm::vec3& min, const glm::vec3& max) {
    const float size = glm::length(max - min);
    const float distance = glm::length(camera.eye - 0.5f * (min + max));
    // The far plane must hold the ground plane drawn around the container; the near plane
    // as far out as possible keeps depth precision.
    camera.farPlane = std::max(distance, size) * 20.0f;
    camera.nearPlane = std::max(size, distance) * 1e-3f;
    return camera;
}

Camera defaultCamera(const glm::vec3& min, const glm::vec3& max) {
    Camera c;
    // A 3/4 view (of a 3D container): from the front-right corner, about 30° above the horizon, at the distance
    // where every corner of the container fits the view (vertical field of view, and the
    // horizontal one of a 4:3 image or wider) with a small margin.
    // A 2D world's container is flat (min.z = max.z): it is seen face on, from +z.
    const glm::vec3 forward = min.z == max.z ? glm::vec3(0.0f, 0.0f, -1.0f) : -glm::normalize(glm::vec3(0.55f, 0.6f, 1.0f));
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
    const glm::vec3 up = glm::cross(right, forward);
    const float tanVertical = 0.92f * std::tan(glm::radians(0.5f * c.fovDegrees));
    const float tanHorizontal = tanVertical * 4.0f / 3.0f;
    c.target = 0.5f * (min + max);
    float distance = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? max.x : min.x, (corner & 2) ? max.y : min.y, (corner & 4) ? max.z : min.z);
        const glm::vec3 r = p - c.target;
        // Seen from eye = target − d·forward, the corner is at depth d + r·forward.
        const float along = glm::dot(r, forward);
        distance = std::max({distance, std::abs(glm::dot(r, up)) / tanVertical - along,
                             std::abs(glm::dot(r, right)) / tanHorizontal - along});
    }
    c.eye = c.target - forward * std::max(distance, 1e-3f);
    return fitClipPlanes(c, min, max);
}

glm::mat4 viewMatrix(const Camera& camera) {
    return glm::lookAt(camera.eye, camera.target, glm::vec3(0.0f, 1.0f, 0.0f));
}

glm::mat4 projectionMatrix(const Camera& camera, float aspect) {
    return glm::perspective(glm::radians(camera.fovDegrees), aspect, camera.nearPlane, camera.farPlane);
}

glm::vec3 projectToPixel(const Camera& camera, int width, int height, const glm::vec3& point) {
    const glm::vec4 eye = viewMatrix(camera) * glm::vec4(point, 1.0f);
    const glm::vec4 clip = projectionMatrix(camera, static_cast<float>(width) / static_cast<float>(height)) * eye;
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    return {(ndc.x * 0.5f + 0.5f) * static_cast<float>(width), (0.5f - ndc.y * 0.5f) * static_cast<float>(height), -eye.z};
}

glm::vec3 pixelRay(const Camera& camera, int width, int height, const glm::vec2& pixel) {
    const float tanHalf = std::tan(glm::radians(0.5f * camera.fovDegrees));
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const float x = (2.0f * pixel.x / static_cast<float>(width) - 1.0f) * tanHalf * aspect;
    const float y = (1.0f - 2.0f * pixel.y / static_cast<float>(height)) * tanHalf;
    const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
    const glm::vec3 up = glm::cross(right, forward);
    return glm::normalize(forward + x * right + y * up);
}

}  // namespace tide::render

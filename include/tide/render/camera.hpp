#pragma once
/// \file
/// A look-at camera, its matrices, and the default view of a container.

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace tide::render {

/// A perspective camera looking from `eye` at `target`, y up.
struct Camera {
    glm::vec3 eye{2.0f, 1.5f, 2.0f};   ///< m
    glm::vec3 target{0.0f};            ///< m
    float fovDegrees = 45.0f;          ///< vertical field of view
    float nearPlane = 0.01f;           ///< m
    float farPlane = 100.0f;           ///< m
};

/// The container `min`..`max` from a 3/4 view above one corner, framed whole.
Camera defaultCamera(const glm::vec3& min, const glm::vec3& max);
/// `camera` with near and far planes fitted to a scene of the container's size.
Camera fitClipPlanes(Camera camera, const glm::vec3& min, const glm::vec3& max);

glm::mat4 viewMatrix(const Camera& camera);
glm::mat4 projectionMatrix(const Camera& camera, float aspect);
/// Pixel (x right, y down, origin top left) where a point appears in a width × height image;
/// z is its distance in front of the camera (negative: behind it).
glm::vec3 projectToPixel(const Camera& camera, int width, int height, const glm::vec3& point);
/// The unit direction of the ray from the eye through a pixel (x right, y down).
glm::vec3 pixelRay(const Camera& camera, int width, int height, const glm::vec2& pixel);

}  // namespace tide::render

#pragma once
// What every pass of one drawn frame shares.
#include <functional>

#include <glm/mat4x4.hpp>

#include "gl.hpp"

namespace tide::render {

struct Frame {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    int width = 0;
    int height = 0;
    float radius = 0.0f;           ///< sprite sphere radius, m
    float pointScale = 0.0f;       ///< sprite diameter px = pointScale · radius / distance
    float spacing = 0.0f;          ///< particle spacing, m
    float extent = 1.0f;           ///< container diagonal, m
    glm::vec3 sunDirection{0.0f, 1.0f, 0.0f};  ///< world, unit
    GLuint emptyVertexArray = 0;
    /// Sets the sphere-vertex uniforms on a program that is in use, and draws every particle.
    std::function<void(const gl::Program&)> drawSpheres;
    /// Draws the solids that can hide fluid (obstacles) into the bound depth buffer only.
    std::function<void()> drawOccluders;
};

}  // namespace tide::render

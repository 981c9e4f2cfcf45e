#pragma once
/// \file
/// tide::render::Renderer — draws a Snapshot with OpenGL 3.3 core: particles as lit sphere
/// impostors, or a water surface by screen-space fluid rendering (van der Laan et al. 2009).
/// Needs a current GL 3.3 core context whose functions are loaded (see HeadlessContext, or
/// a GLFW window plus loadGlFunctions()).

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <tide/render/camera.hpp>
#include <tide/render/snapshot.hpp>

namespace tide::render {

enum class RenderMode {
    Particles,  ///< each particle a lit sphere
    Surface,    ///< the water surface: reflection, refraction, absorption, foam
};

/// What particles are coloured by (Particles mode).
enum class ColorBy { Material, Speed, Density, Pressure };

/// Materials a renderer shows individually; later ones share the last slot's settings.
inline constexpr int kMaxRenderMaterials = 16;

struct RenderSettings {
    RenderMode mode = RenderMode::Surface;
    ColorBy colorBy = ColorBy::Material;
    /// Range mapped onto the colour map (speed m/s, density kg/m³, pressure Pa); when
    /// min ≥ max the renderer picks the snapshot's own range and reports it in lastRange().
    glm::vec2 range{0.0f, 0.0f};
    std::array<bool, kMaxRenderMaterials> visible = filled(true);
    /// Per-material colour overrides; a negative red keeps the material's own colour.
    std::array<glm::vec3, kMaxRenderMaterials> color = filled(glm::vec3(-1.0f));
    float particleScale = 1.0f;           ///< sprite radius in half particle spacings
    int smoothingIterations = 3;          ///< surface: depth filter passes
    bool foam = true;                     ///< surface: whitecaps from fast surface particles
    bool showContainer = true;            ///< the container's edges

    template <typename T>
    static constexpr std::array<T, kMaxRenderMaterials> filled(const T& value) {
        std::array<T, kMaxRenderMaterials> a{};
        a.fill(value);
        return a;
    }
};

/// The colour map for scalar fields (and its legend): t in [0, 1], linear RGB.
glm::vec3 colormap(float t);

/// Name of a colouring, for legends: "speed (m/s)" etc.
const char* colorByName(ColorBy colorBy);

class Renderer {
public:
    /// Compiles the shaders; throws std::runtime_error with the compiler's log on failure.
    Renderer();
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    /// Draw into `framebuffer` (0: the window), `width` × `height` pixels.
    void draw(const Snapshot& snapshot, const Camera& camera, const RenderSettings& settings, int width, int height,
              unsigned framebuffer = 0);
    /// The scalar range the last draw mapped onto the colour map.
    [[nodiscard]] glm::vec2 lastRange() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// Load the GL function pointers (GLEW) for the current context; throws std::runtime_error.
void loadGlFunctions();

}  // namespace tide::render

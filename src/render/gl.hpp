#pragma once
// GL through GLEW, and the few RAII helpers the passes share: programs, textures, framebuffers.
#include <GL/glew.h>

#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace tide::render::gl {

/// A linked vertex + fragment program. Throws std::runtime_error with the info log.
class Program {
public:
    Program(const char* name, const char* vertexSource, const char* fragmentSource);
    ~Program();
    Program(const Program&) = delete;
    Program& operator=(const Program&) = delete;

    void use() const { glUseProgram(id_); }
    [[nodiscard]] GLint location(const char* uniform) const { return glGetUniformLocation(id_, uniform); }
    void set(const char* uniform, int v) const { glUniform1i(location(uniform), v); }
    void set(const char* uniform, unsigned v) const { glUniform1ui(location(uniform), v); }
    void set(const char* uniform, float v) const { glUniform1f(location(uniform), v); }
    void set(const char* uniform, const glm::vec2& v) const { glUniform2f(location(uniform), v.x, v.y); }
    void set(const char* uniform, const glm::vec3& v) const { glUniform3f(location(uniform), v.x, v.y, v.z); }
    void set(const char* uniform, const glm::vec4& v) const { glUniform4f(location(uniform), v.x, v.y, v.z, v.w); }
    void set(const char* uniform, const glm::mat4& m) const;

private:
    GLuint id_ = 0;
};

/// A 2D texture, sampled with nearest filtering and clamped edges.
class Texture {
public:
    Texture() = default;
    ~Texture() { release(); }
    Texture(const Texture&) = delete;
    Texture& operator=(const Texture&) = delete;

    /// (Re)allocate at width × height in `internalFormat` (e.g. GL_R32F, GL_RGBA8).
    void allocate(int width, int height, GLenum internalFormat, GLenum format, GLenum type, bool linear = false);
    void bind(int unit) const;
    [[nodiscard]] GLuint id() const { return id_; }

private:
    void release();
    GLuint id_ = 0;
};

/// A framebuffer over colour textures and an optional depth renderbuffer.
class Framebuffer {
public:
    Framebuffer() = default;
    ~Framebuffer() { release(); }
    Framebuffer(const Framebuffer&) = delete;
    Framebuffer& operator=(const Framebuffer&) = delete;

    /// Attach colour textures (and a fresh depth buffer when width > 0); throws if incomplete.
    void attach(std::initializer_list<const Texture*> colours, int depthWidth = 0, int depthHeight = 0);
    void bind() const { glBindFramebuffer(GL_FRAMEBUFFER, id_); }
    [[nodiscard]] GLuint id() const { return id_; }

private:
    void release();
    GLuint id_ = 0;
    GLuint depth_ = 0;
};

/// Draws one triangle covering the viewport (full-screen passes); core profile needs some
/// vertex array bound even when the vertex shader makes up the vertices: pass an empty one.
void drawFullscreenTriangle(GLuint emptyVertexArray);

}  // namespace tide::render::gl

// Program, texture and framebuffer helpers; GLEW loading.
#include "gl.hpp"

#include <stdexcept>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include <tide/render/renderer.hpp>

namespace tide::render {

void loadGlFunctions() {
    glewExperimental = GL_TRUE;
    const GLenum status = glewInit();
    // GLEW 2.2 (GLX build) loads every GL function first, then fails looking for a GLX display
    // when the context is EGL's: the functions are loaded all the same.
    if (status != GLEW_OK && status != GLEW_ERROR_NO_GLX_DISPLAY)
        throw std::runtime_error(std::string("cannot load OpenGL functions: ") +
                                 reinterpret_cast<const char*>(glewGetErrorString(status)));
    glGetError();  // glewInit may leave GL_INVALID_ENUM behind on core profiles
    if (!glGenFramebuffers || !glCreateShader) throw std::runtime_error("OpenGL 3.3 functions are missing");
}

namespace gl {

namespace {

GLuint compile(const char* name, GLenum stage, const char* source) {
    const GLuint shader = glCreateShader(stage);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
        std::vector<char> log(static_cast<std::size_t>(length) + 1);
        glGetShaderInfoLog(shader, length, nullptr, log.data());
        glDeleteShader(shader);
        throw std::runtime_error(std::string("shader ") + name + (stage == GL_VERTEX_SHADER ? " (vertex)" : " (fragment)") +
                                 ": " + log.data());
    }
    return shader;
}

}  // namespace

Program::Program(const char* name, const char* vertexSource, const char* fragmentSource) {
    const GLuint vs = compile(name, GL_VERTEX_SHADER, vertexSource);
    const GLuint fs = compile(name, GL_FRAGMENT_SHADER, fragmentSource);
    id_ = glCreateProgram();
    glAttachShader(id_, vs);
    glAttachShader(id_, fs);
    glLinkProgram(id_);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(id_, GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(id_, GL_INFO_LOG_LENGTH, &length);
        std::vector<char> log(static_cast<std::size_t>(length) + 1);
        glGetProgramInfoLog(id_, length, nullptr, log.data());
        glDeleteProgram(id_);
        throw std::runtime_error(std::string("program ") + name + ": " + log.data());
    }
}

Program::~Program() { glDeleteProgram(id_); }

void Program::set(const char* uniform, const glm::mat4& m) const {
    glUniformMatrix4fv(location(uniform), 1, GL_FALSE, glm::value_ptr(m));
}

void Texture::allocate(int width, int height, GLenum internalFormat, GLenum format, GLenum type, bool linear) {
    if (!id_) glGenTextures(1, &id_);
    glBindTexture(GL_TEXTURE_2D, id_);
    glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internalFormat), width, height, 0, format, type, nullptr);
    const GLint filter = linear ? GL_LINEAR : GL_NEAREST;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void Texture::bind(int unit) const {
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, id_);
}

void Texture::release() {
    if (id_) glDeleteTextures(1, &id_);
    id_ = 0;
}

void Framebuffer::attach(std::initializer_list<const Texture*> colours, int depthWidth, int depthHeight) {
    if (!id_) glGenFramebuffers(1, &id_);
    glBindFramebuffer(GL_FRAMEBUFFER, id_);
    std::vector<GLenum> buffers;
    for (const Texture* t : colours) {
        const auto attachment = static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + buffers.size());
        glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, t->id(), 0);
        buffers.push_back(attachment);
    }
    glDrawBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
    if (depthWidth > 0) {
        if (!depth_) glGenRenderbuffers(1, &depth_);
        glBindRenderbuffer(GL_RENDERBUFFER, depth_);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, depthWidth, depthHeight);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    }
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("framebuffer incomplete (status 0x" + std::to_string(status) + ")");
}

void Framebuffer::release() {
    if (depth_) glDeleteRenderbuffers(1, &depth_);
    if (id_) glDeleteFramebuffers(1, &id_);
    depth_ = id_ = 0;
}

void drawFullscreenTriangle(GLuint emptyVertexArray) {
    glBindVertexArray(emptyVertexArray);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace gl
}  // namespace tide::render

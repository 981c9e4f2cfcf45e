#pragma once
// Running the `tide` executable from tests as a user would: a command's exit code and output,
// and scratch folders per test process.
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace tide::testing {

namespace fs = std::filesystem;

struct Result {
    int exit;
    std::string output;  ///< stdout and stderr together
};

inline Result run(const std::string& command) {
    Result r{-1, {}};
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buffer{};
    std::size_t n;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) r.output.append(buffer.data(), n);
    const int status = pclose(pipe);
    r.exit = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

inline fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("tide_cli_test_" + std::to_string(::getpid())) / name;
    fs::remove_all(dir);
    fs::create_directories(dir.parent_path());
    return dir;
}

inline fs::path writeScene(const std::string& name, const std::string& text) {
    const fs::path file = scratch(name + ".json");
    std::ofstream(file) << text;
    return file;
}

}  // namespace tide::testing

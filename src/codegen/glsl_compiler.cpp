#include "codegen/glsl_compiler.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <stdexcept>

#include <fmt/format.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <unistd.h>

namespace simeco::codegen {

namespace {

namespace fs = std::filesystem;

// glslang's process-wide state, set up once.
void initializeGlslang() {
    static std::once_flag once;
    std::call_once(once, [] {
        glslang::InitializeProcess();
        std::atexit([] { glslang::FinalizeProcess(); });
    });
}

// FNV-1a, 64 bits: a content hash for cache file names (the compiler version is part of the key).
uint64_t contentHash(const std::string& text) {
    uint64_t h = 0xcbf29ce484222325ull;
    for (unsigned char c : text) {
        h ^= c;
        h *= 0x100000001b3ull;
    }
    return h;
}

fs::path cacheDirectory() {
    if (const char* dir = std::getenv("SIMECO_KERNEL_CACHE"); dir && *dir) return dir;
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return fs::path(xdg) / "simeco" / "kernels";
    if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".cache" / "simeco" / "kernels";
    return {};
}

} // namespace

std::vector<std::uint32_t> compileComputeKernel(const std::string& source, const std::string& name) {
    initializeGlslang();
    glslang::TShader shader(EShLangCompute);
    const char* text = source.c_str();
    const char* names = name.c_str();
    shader.setStringsWithLengthsAndNames(&text, nullptr, &names, 1);
    shader.setEnvInput(glslang::EShSourceGlsl, EShLangCompute, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_5);
    EShMessages messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
    if (!shader.parse(GetDefaultResources(), 460, false, messages))
        throw std::runtime_error(fmt::format("kernel {} does not compile:\n{}", name, shader.getInfoLog()));
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages))
        throw std::runtime_error(fmt::format("kernel {} does not link:\n{}", name, program.getInfoLog()));
    std::vector<std::uint32_t> spirv;
    glslang::SpvOptions options;
    options.disableOptimizer = true; // the driver optimizes anyway; glslang's pass costs more than it saves here
    glslang::GlslangToSpv(*program.getIntermediate(EShLangCompute), spirv, &options);
    return spirv;
}

std::vector<std::uint32_t> cachedComputeKernel(const std::string& source, const std::string& name, bool* fromCache) {
    if (fromCache) *fromCache = false;
    // For looking at generated code: SIMECO_DUMP_KERNELS=DIR writes each kernel's GLSL there.
    if (const char* dump = std::getenv("SIMECO_DUMP_KERNELS"); dump && *dump) {
        std::error_code ec;
        fs::path file = fs::path(dump) / (name + ".comp");
        fs::create_directories(file.parent_path(), ec);
        std::ofstream(file) << source;
    }
    fs::path dir = cacheDirectory();
    std::string key = fmt::format("{:016x}-{}", contentHash(std::string(glslang::GetGlslVersionString()) + source),
                                  source.size());
    fs::path file = dir.empty() ? fs::path() : dir / (key + ".spv");
    std::error_code ec;
    if (!file.empty() && fs::is_regular_file(file, ec)) {
        std::ifstream in(file, std::ios::binary);
        std::vector<std::uint32_t> words(fs::file_size(file, ec) / 4);
        if (in.read(reinterpret_cast<char*>(words.data()), static_cast<std::streamsize>(words.size() * 4)) &&
            !words.empty() && words[0] == 0x07230203u) {
            if (fromCache) *fromCache = true;
            return words;
        }
    }
    std::vector<std::uint32_t> words = compileComputeKernel(source, name);
    if (!file.empty()) {
        // Written under a temporary name and renamed, so a concurrent reader never sees half a file.
        fs::create_directories(dir, ec);
        fs::path temporary = dir / (key + fmt::format(".{}.tmp", ::getpid()));
        {
            std::ofstream out(temporary, std::ios::binary);
            out.write(reinterpret_cast<const char*>(words.data()), static_cast<std::streamsize>(words.size() * 4));
        }
        fs::rename(temporary, file, ec);
        if (ec) fs::remove(temporary, ec);
    }
    return words;
}

} // namespace simeco::codegen

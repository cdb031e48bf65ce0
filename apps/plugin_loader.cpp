#include "apps/plugin_loader.hpp"

#include <dlfcn.h>
#include <fmt/format.h>

#include <filesystem>
#include <set>
#include <system_error>

#include "apps/input_error.hpp"
#include "sim/plugin.hpp"

namespace covsim::app {

void add_plugin_option(CLI::App* cmd, std::vector<std::string>& plugins) {
  cmd->add_option("--plugin", plugins,
                  "Shared library that registers components (repeatable); see docs/extending.md");
}

void load_plugins(const std::vector<std::string>& plugins) {
  static std::set<std::string> loaded;  // a library registers once per process
  for (const std::string& given : plugins) {
    // A file, as the user named it: a bare name is in the working folder, never looked up in
    // the system's library path (which would load whatever library has that name).
    std::error_code ec;
    const std::filesystem::path path = std::filesystem::absolute(given, ec);
    if (ec || !std::filesystem::is_regular_file(path, ec))
      throw InputError(
          fmt::format("--plugin {}: no such file (a plugin is a shared library "
                      "file, named by its path)",
                      given));
    const std::string file = path.string();
    // One library once, however it is named (./p.so, p.so, a link to it).
    if (!loaded.insert(std::filesystem::weakly_canonical(path, ec).string()).second) continue;
    void* lib = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (lib == nullptr)
      throw InputError(fmt::format("--plugin {}: cannot load it: {}", given, dlerror()));
    const auto version = reinterpret_cast<int (*)()>(dlsym(lib, "covsim_plugin_api_version"));
    const auto built_with =
        reinterpret_cast<const char* (*)()>(dlsym(lib, "covsim_plugin_covsim_version"));
    const auto do_register =
        reinterpret_cast<void (*)(Registries*)>(dlsym(lib, "covsim_plugin_register"));
    if (version == nullptr || built_with == nullptr || do_register == nullptr) {
      throw InputError(fmt::format(
          "--plugin {}: not a covsim plugin (it defines no COVSIM_PLUGIN entry points)", given));
    }
    if (version() != kPluginApiVersion) {
      const char* its_covsim = built_with();
      throw InputError(fmt::format(
          "--plugin {}: built for covsim plugin API {} (covsim {}); this covsim {} has plugin "
          "API {}: rebuild the plugin against this covsim",
          given, version(), its_covsim != nullptr ? its_covsim : "of no stated version", kVersion,
          kPluginApiVersion));
    }
    Registries r = registries();
    try {
      do_register(&r);
    } catch (const std::exception& e) {
      throw InputError(
          fmt::format("--plugin {}: registering its components failed: {}", given, e.what()));
    } catch (...) {
      throw InputError(fmt::format(
          "--plugin {}: registering its components failed (it threw a non-standard exception)",
          given));
    }
  }
}

}  // namespace covsim::app

#pragma once
// What built this covsim, for provenance records (final.json, a sweep's sweep.json, a trace's
// header, `covsim --version`): results are bit-identical between builds only if what affects
// them agrees. Generated at build time (cmake/BuildInfo.cmake).
namespace covsim {

struct BuildInfo {
  const char* version;     // project(covsim VERSION ...)
  const char* commit;      // git commit of the sources, "unknown" outside a git tree
  bool dirty;              // tracked files differed from that commit
  const char* compiler;    // "GNU 12.2.0"
  const char* build_type;  // "Release"
  const char* flags;       // the compiler flags that affect results
};

const BuildInfo& build_info();

}  // namespace covsim

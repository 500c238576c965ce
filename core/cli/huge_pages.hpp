// huge_pages.hpp — the native programs (the CLI and the benchmarks) run with glibc's malloc backing
// its blocks by transparent huge pages, by re-executing themselves once with the glibc tunable that
// asks for it.
//
// Why: a 1M-vertex parameterization allocates a few hundred MB in blocks of 8–100 MB (meshes, sparse
// matrices, the solver's vectors); with 4 KiB pages the first touch of every page is a fault, and on a
// virtual machine a fault is expensive. On the 2-core development VM, solving the 1M height field's
// system took 305k minor faults and ~1 s more than with huge pages (10k faults), and a one-shot CLI
// run meets every one of them. Where the kernel's THP mode is "madvise" (Debian's default), only memory
// that asks for huge pages gets them — which malloc does when glibc.malloc.hugetlb=1 is set, and that
// tunable is read only at process start, hence the re-exec. Mode "always" needs nothing and "never"
// allows nothing: no re-exec then, nor where the variable already names the tunable (the user's choice
// stands: GLIBC_TUNABLES=glibc.malloc.hugetlb=0 turns this off). Programs that link the library
// themselves can set the variable in their environment; WebAssembly has no such choice.
#pragma once
#include <string>

#if defined(__GLIBC__) && !defined(__EMSCRIPTEN__)
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#endif

namespace straightest::cli {

inline constexpr const char* kHugePageTunable = "glibc.malloc.hugetlb";

/// The GLIBC_TUNABLES value that adds glibc.malloc.hugetlb=1 to `current` (null: unset); "" when
/// `current` already names that tunable, whatever its value.
inline std::string tunablesWithHugePages(const char* current) {
  const std::string setting = std::string(kHugePageTunable) + "=1";
  if (current == nullptr || *current == '\0') return setting;
  const std::string value = current;
  // Tunables are colon-separated name=value pairs: match the name at the start of a pair.
  const std::string name = std::string(kHugePageTunable) + "=";
  for (size_t at = value.find(name); at != std::string::npos; at = value.find(name, at + 1))
    if (at == 0 || value[at - 1] == ':') return "";
  return value + ":" + setting;
}

/// Re-executes this program (same arguments, same process id) with huge pages asked for, when that can
/// help (see above); returns only when it does not re-execute or the exec fails — then the program
/// simply runs with ordinary pages.
inline void reexecWithHugePages(char** argv) {
#if defined(__GLIBC__) && !defined(__EMSCRIPTEN__)
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  if (!std::getline(mode, line) || line.find("[madvise]") == std::string::npos) return;
  const char* before = std::getenv("GLIBC_TUNABLES");
  const std::string tunables = tunablesWithHugePages(before);
  if (tunables.empty()) return;
  char self[4096];
  const ssize_t length = readlink("/proc/self/exe", self, sizeof self - 1);
  if (length <= 0) return;
  self[length] = '\0';
  const std::string previous = before ? before : "";
  if (setenv("GLIBC_TUNABLES", tunables.c_str(), 1) != 0) return;
  execv(self, argv);
  // The exec failed: leave the environment as it was.
  if (before) setenv("GLIBC_TUNABLES", previous.c_str(), 1);
  else unsetenv("GLIBC_TUNABLES");
#else
  (void)argv;
#endif
}

}  // namespace straightest::cli

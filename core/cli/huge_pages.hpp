// huge_pages.hpp — the native programs (the CLI and the benchmarks) run with glibc's malloc backing
// its blocks by transparent huge pages and keeping freed memory for reuse, by re-executing themselves
// once with the glibc tunables that ask for it.
//
// Why: a large parameterization allocates its memory in large blocks (meshes, sparse matrices, the
// solver's vectors); with 4 KiB pages the first touch of every page is a fault, and on a
// virtual machine a fault is expensive; huge pages take a fraction of the faults, and a one-shot CLI
// run meets every one of them. Where the kernel's THP mode is "madvise" (Debian's default), only memory
// that asks for huge pages gets them — which malloc does when glibc.malloc.hugetlb=1 is set; and
// memory freed by one stage and taken by the next is zeroed again by the kernel unless malloc keeps it
// (at the same peak memory). Figures in docs/BENCHMARKS.md. Tunables
// are read only at process start, hence the re-exec. Mode "always" needs nothing and "never"
// allows nothing: no re-exec then, nor where the variable already names the tunable (the user's choice
// stands: GLIBC_TUNABLES=glibc.malloc.hugetlb=0 turns this off). Programs that link the library
// themselves can set the variable in their environment; WebAssembly has no such choice. (The exact
// geodesics' arrays ask for huge pages themselves, core/src/huge_page_allocator.hpp, wherever the
// library runs; these tunables cover every other allocation of the CLI.)
#pragma once
#include <string>

#if defined(__GLIBC__) && !defined(__EMSCRIPTEN__)
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#endif

namespace straightest::cli {

/// The tunables set, as name=value: huge pages for malloc's blocks; and no block handed back to the
/// kernel while the program runs (no mmap'd blocks, which go back on free; no trimming of the heap),
/// so that a stage reuses pages an earlier one touched instead of faulting in freshly zeroed ones — a
/// one-shot CLI run frees and allocates its large buffers stage after stage.
inline constexpr const char* kTunables[] = {"glibc.malloc.hugetlb=1", "glibc.malloc.mmap_max=0",
                                            "glibc.malloc.trim_threshold=17179869184"};

/// Whether the colon-separated tunables in `value` name `name` (the part before '=').
inline bool namesTunable(const std::string& value, const std::string& name) {
  for (size_t at = value.find(name + "="); at != std::string::npos; at = value.find(name + "=", at + 1))
    if (at == 0 || value[at - 1] == ':') return true;
  return false;
}

/// The GLIBC_TUNABLES value that adds kTunables to `current` (null: unset), each unless `current`
/// names it already; "" when `current` names glibc.malloc.hugetlb (the user's choice, or this
/// program already re-executed: nothing to do).
inline std::string tunablesWithHugePages(const char* current) {
  std::string value = current ? current : "";
  if (namesTunable(value, "glibc.malloc.hugetlb")) return "";
  for (const char* tunable : kTunables) {
    const std::string setting = tunable;
    const std::string name = setting.substr(0, setting.find('='));
    if (namesTunable(value, name)) continue;
    value += (value.empty() ? "" : ":") + setting;
  }
  return value;
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

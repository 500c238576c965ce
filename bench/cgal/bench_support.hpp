// bench_support.hpp — what every part of bench_cgal shares: times (median of repeats), process memory,
// a tiny JSON writer, number formatting for the tables, and OUR texture stretch of any UV set (one
// metric for every method, CGAL's included).
#pragma once
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <malloc.h>

#include "straightest/param/texture_stretch.hpp"

namespace bench_cgal {

using namespace straightest;
using Clock = std::chrono::steady_clock;

inline constexpr double kInf = std::numeric_limits<double>::infinity();

inline double msSince(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

inline double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Resident memory of this process in MB from /proc/self/status (VmRSS now, VmHWM the peak); -1 when
// unavailable. resetPeakRss() hands freed heap back to the system (malloc_trim) and resets the peak to
// the current RSS (writing "5" to clear_refs), so a stage's peak minus its baseline is what it added.
inline double statusMb(const char* key) {
  std::ifstream f("/proc/self/status");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind(key, 0) == 0) return std::atof(line.c_str() + std::strlen(key)) / 1024.0;
  return -1;
}
inline double resetPeakRss() {
  malloc_trim(0);
  std::ofstream f("/proc/self/clear_refs");
  if (f) f << "5";
  f.close();
  return statusMb("VmRSS:");
}
inline double peakRssMb() { return statusMb("VmHWM:"); }
inline double memAvailableMb() {
  std::ifstream f("/proc/meminfo");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind("MemAvailable:", 0) == 0) return std::atof(line.c_str() + 13) / 1024.0;
  return -1;
}

// ------------------------------------------------------------------ a tiny JSON writer
inline std::string num(double x, int digits = 6) {
  if (!std::isfinite(x)) return "null";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}
inline std::string str(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}
struct Obj {
  std::string body;
  Obj& add(const std::string& k, const std::string& rawValue) {
    body += (body.empty() ? "" : ",") + str(k) + ":" + rawValue;
    return *this;
  }
  Obj& add(const std::string& k, double v, int digits = 6) { return add(k, num(v, digits)); }
  Obj& add(const std::string& k, int64_t v) { return add(k, std::to_string(v)); }
  Obj& add(const std::string& k, int v) { return add(k, std::to_string(v)); }
  Obj& add(const std::string& k, bool v) { return add(k, std::string(v ? "true" : "false")); }
  Obj& addStr(const std::string& k, const std::string& v) { return add(k, str(v)); }
  std::string done() const { return "{" + body + "}"; }
};
inline std::string array(const std::vector<double>& v, int digits = 9) {
  std::string out = "[";
  for (size_t i = 0; i < v.size(); ++i) out += (i ? "," : "") + num(v[i], digits);
  return out + "]";
}

// ------------------------------------------------------------------ measurements
struct Timed {
  double ms = kInf;  // median
  int runs = 0;
};

/// Runs f `repeats` times (once only when the first run exceeds onceAboveMs) and returns the median.
inline Timed timeIt(int repeats, double onceAboveMs, const std::function<void()>& f) {
  std::vector<double> t;
  for (int i = 0; i < repeats; ++i) {
    const auto start = Clock::now();
    f();
    t.push_back(msSince(start));
    if (i == 0 && t[0] > onceAboveMs) break;
  }
  return {median(t), static_cast<int>(t.size())};
}

struct Stretch {
  StretchMetrics m;
  bool mirrored = false;
};

/// Our texture stretch of a UV set. A map that is a reflection of a counter-clockwise one (total
/// signed area negative: e.g. CGAL's circle runs the other way round) is mirrored first — stretch
/// does not change under a reflection of the whole map, but our flip test is orientation-aware.
inline Stretch stretchOf(const TriMesh& mesh, std::vector<Vec2> uv) {
  double area = 0;
  for (const Triangle& t : mesh.triangles()) {
    const Vec2 &a = uv[t[0]], &b = uv[t[1]], &c = uv[t[2]];
    area += (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  }
  Stretch s;
  if (area < 0) {
    s.mirrored = true;
    for (Vec2& p : uv) p[0] = -p[0];
  }
  s.m = textureStretch(mesh, uv);
  return s;
}

inline void stretchFields(Obj& o, const Stretch& s) {
  o.add("l2", s.m.l2, 9).add("linf", s.m.linf, 9).add("flipped", s.m.flipped).add("degenerate", s.m.degenerate);
}

inline std::string fmtMs(double x) {
  if (!std::isfinite(x)) return "—";
  char buf[64];
  std::snprintf(buf, sizeof buf, x < 10 ? "%.2f" : x < 100 ? "%.1f" : "%.0f", x);
  return buf;
}

inline std::string fmt(double x, const char* f) {
  if (!std::isfinite(x)) return "—";
  char buf[64];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}
}  // namespace bench_cgal

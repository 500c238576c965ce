// json_writer.hpp — the CLI's visitor of result_fields.hpp: each field as JSON (nlohmann, keys in
// snake_case, a vertex point as its index, non-finite numbers as null); large arrays and per-path
// columns are left out (the CLI prints a summary and one row per path instead).
#pragma once
#include <cctype>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "straightest/api/result_fields.hpp"

namespace straightest::cli {

using json = nlohmann::ordered_json;

/// "weightFallbacks" → "weight_fallbacks".
inline std::string snakeCase(const char* camel) {
  std::string out;
  for (const char* c = camel; *c; ++c) {
    if (std::isupper(static_cast<unsigned char>(*c))) {
      out += '_';
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(*c)));
    } else {
      out += *c;
    }
  }
  return out;
}

inline json vec3Json(const Vec3& v) { return json::array({v.x, v.y, v.z}); }

inline json pointJson(const SurfacePoint& p) {
  switch (p.kind) {
    case SurfacePoint::Kind::Vertex: return p.index;
    case SurfacePoint::Kind::Edge: return json{{"halfedge", p.index}, {"t", p.t}};
    case SurfacePoint::Kind::Face: return json{{"face", p.index}, {"bary", p.bary}};
  }
  return nullptr;
}

class JsonWriter {
 public:
  explicit JsonWriter(json& out) : out_(out) { out_ = json::object(); }

  void number(const char* name, double x) { at(name) = x; }  // nlohmann writes inf and NaN as null
  void count(const char* name, int64_t x) { at(name) = x; }
  void flag(const char* name, bool b) { at(name) = b; }
  void text(const char* name, const std::string& s) { at(name) = s; }
  void point(const char* name, const SurfacePoint& p) { at(name) = pointJson(p); }
  void vec3(const char* name, const Vec3& v) { at(name) = vec3Json(v); }
  void nothing(const char* name) { at(name) = nullptr; }
  void counts(const char* name, const std::vector<int64_t>& xs) { at(name) = xs; }
  void texts(const char* name, const std::vector<std::string>& xs) { at(name) = xs; }
  template <class Fill>
  void object(const char* name, Fill&& fill) {
    JsonWriter child(at(name));
    fill(child);
  }
  template <class T>
  void list(const char* name, const std::vector<T>& items) {
    json& array = at(name) = json::array();
    for (const T& item : items) {
      json entry;
      JsonWriter child(entry);
      visitFields(item, child);
      array.push_back(std::move(entry));
    }
  }
  template <class T>
  void bulk(const char*, const T*, size_t, Bulk) {}
  void points(const char*, const std::vector<SurfacePoint>&) {}
  void textColumn(const char*, const std::vector<std::string>&) {}

 private:
  json& at(const char* name) { return out_[snakeCase(name)]; }
  json& out_;
};

/// A result's fields as a JSON object.
template <class T>
json toJson(const T& result) {
  json out;
  JsonWriter writer(out);
  visitFields(result, writer);
  return out;
}

}  // namespace straightest::cli

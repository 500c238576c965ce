#include "straightest/mesh_format_name.hpp"

#include "straightest/enum_names.hpp"

#include <cctype>
#include <string>

namespace straightest {

MeshFormat formatFromFileName(std::string_view name) {
  const size_t slash = name.find_last_of("/\\");
  const std::string_view base = slash == std::string_view::npos ? name : name.substr(slash + 1);
  const size_t dot = base.rfind('.');
  if (dot == std::string_view::npos) return MeshFormat::Auto;
  std::string ext;
  for (char c : base.substr(dot + 1)) ext += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return valueOf(kMeshFormatNames, ext).value_or(MeshFormat::Auto);
}

}  // namespace straightest

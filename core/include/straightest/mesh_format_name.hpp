// mesh_format_name.hpp — which reader a file's name asks for: its extension, case-insensitively
// (".obj" → obj, ".off" → off), anything else → auto (the reader looks at the content). The page, the
// npm package and the CLI all ask this one function.
#pragma once
#include <string_view>

#include "straightest/mesh_io.hpp"

namespace straightest {

MeshFormat formatFromFileName(std::string_view name);

}  // namespace straightest

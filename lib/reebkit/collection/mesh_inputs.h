// The meshes of a collection to index (reeb index INPUT...): folders searched
// recursively, list files, or mesh files, turned into one ordered list of
// (path, name). The name is what the collection file calls the mesh, so it
// is unique and does not depend on where the collection sits on disk.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace reebkit {

struct MeshInput {
  std::filesystem::path path;  ///< where to read the mesh
  std::string name;            ///< its name in the collection (generic '/' separators)
};

/// The mesh file extensions listed from folders, lower case.
inline constexpr const char* kMeshExtensions[] = {".off", ".obj", ".ply", ".stl"};

/// Natural order: `a` before `b` comparing runs of digits by their value and
/// everything else character by character, so that 2.off < 10.off and
/// pose2 < pose10. Names equal but for leading zeros ("a01", "a1") fall back
/// to plain comparison, so that the order is total: natural_less(a, b) or
/// natural_less(b, a) unless a == b.
bool natural_less(std::string_view a, std::string_view b);

/// The meshes named by `inputs`, in order; each input is
///  - a folder: every file below it (recursively) whose extension is a mesh
///    extension in any case (.off .OFF .obj ...), in the natural order of
///    their names (natural_less: 1.off, 2.off, ..., 10.off); named by its
///    path relative to the folder ("arms/star.off");
///  - a list file (.txt or .lst): one mesh path per line, relative to the
///    list file's folder unless absolute; blank lines and everything after
///    a '#' are ignored; named as written on the line;
///  - a mesh file (.off .obj .ply .stl): named by the path as given.
/// Throws InvalidArgument listing every input or listed path that does not
/// exist (with the list file and line), an input of an unknown kind, and two
/// meshes with the same name (naming both paths).
std::vector<MeshInput> list_mesh_inputs(const std::vector<std::string>& inputs);

}  // namespace reebkit

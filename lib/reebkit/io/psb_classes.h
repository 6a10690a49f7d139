// Class labels of a collection from a Princeton Shape Benchmark .cla file
// (Shilane et al. 2004), the format SHREC 2007 distributes its classes in:
//
//   PSB 1
//   <number of classes> <number of models>
//   <class name> <parent class name or 0> <number of models in it>
//   <model id>            (one per line, that many)
//   ...                   (blank lines between blocks are ignored)
#pragma once

#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

namespace reebkit {

struct PsbClass {
  std::string name;
  std::string parent;               ///< "0" for a top-level class
  std::vector<std::string> models;  ///< model ids, in file order
};

/// Model id -> class name.
using ClassMap = std::unordered_map<std::string, std::string>;

/// The classes of a .cla file, in file order. Throws Error
/// "<file>:<line>: <problem>" on a missing header, a wrong count, a
/// truncated block or a model listed twice.
std::vector<PsbClass> read_psb_classes(const std::filesystem::path& path);

/// Model id -> class name of `classes`.
ClassMap class_map(const std::vector<PsbClass>& classes);

/// The class of the mesh called `mesh_name` in a collection ("" when none):
/// looked up by the name, then without its extension, then by the file name
/// without extension ("arms/17.off" -> "arms/17.off", "arms/17", "17"), so
/// that PSB model ids match the files named after them.
std::string class_of(const ClassMap& classes, const std::string& mesh_name);

}  // namespace reebkit

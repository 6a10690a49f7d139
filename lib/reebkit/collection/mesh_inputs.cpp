#include "reebkit/collection/mesh_inputs.h"

#include "reebkit/core/error.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>

namespace reebkit {
namespace {

namespace fs = std::filesystem;

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool is_mesh_file(const fs::path& path) {
  const std::string ext = lower(path.extension().string());
  return std::any_of(std::begin(kMeshExtensions), std::end(kMeshExtensions), [&](const char* e) { return ext == e; });
}

bool is_list_file(const fs::path& path) {
  const std::string ext = lower(path.extension().string());
  return ext == ".txt" || ext == ".lst";
}

/// Every mesh file below `folder`, in the natural order of their names (relative paths).
void list_folder(const fs::path& folder, std::vector<MeshInput>& out) {
  std::vector<MeshInput> found;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(folder)) {
    if (e.is_regular_file() && is_mesh_file(e.path()))
      found.push_back({e.path(), e.path().lexically_relative(folder).generic_string()});
  }
  std::sort(found.begin(), found.end(),
            [](const MeshInput& a, const MeshInput& b) { return natural_less(a.name, b.name); });
  out.insert(out.end(), found.begin(), found.end());
}

/// The meshes of a list file; missing ones are added to `missing`.
void list_file(const fs::path& list, std::vector<MeshInput>& out, std::vector<std::string>& missing) {
  std::ifstream in(list);
  if (!in) throw InvalidArgument(list.string() + ": cannot open the list file");
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    line = line.substr(0, line.find('#'));
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    const std::string written = line.substr(first, line.find_last_not_of(" \t\r") + 1 - first);
    const fs::path path = fs::path(written).is_absolute() ? fs::path(written) : list.parent_path() / written;
    if (!fs::is_regular_file(path))
      missing.push_back(list.string() + ":" + std::to_string(number) + ": " + path.string());
    else
      out.push_back({path, fs::path(written).lexically_normal().generic_string()});
  }
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

/// The run of digits of `text` starting at `at`, without its leading zeros; `at` moves past the run.
std::string_view digit_run(std::string_view text, std::size_t& at) {
  while (at < text.size() && text[at] == '0' && at + 1 < text.size() && is_digit(text[at + 1])) ++at;
  const std::size_t begin = at;
  while (at < text.size() && is_digit(text[at])) ++at;
  return text.substr(begin, at - begin);
}

}  // namespace

bool natural_less(std::string_view a, std::string_view b) {
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (is_digit(a[i]) && is_digit(b[j])) {
      // Values compare by length without leading zeros, then digit by digit: no overflow.
      const std::string_view x = digit_run(a, i), y = digit_run(b, j);
      if (x.size() != y.size()) return x.size() < y.size();
      if (x != y) return x < y;
    } else {
      if (a[i] != b[j]) return static_cast<unsigned char>(a[i]) < static_cast<unsigned char>(b[j]);
      ++i;
      ++j;
    }
  }
  if ((i < a.size()) != (j < b.size())) return j < b.size();  // a prefix comes first
  return a < b;
}

std::vector<MeshInput> list_mesh_inputs(const std::vector<std::string>& inputs) {
  std::vector<MeshInput> out;
  std::vector<std::string> missing;
  for (const std::string& input : inputs) {
    const fs::path path(input);
    if (fs::is_directory(path))
      list_folder(path, out);
    else if (!fs::exists(path))
      missing.push_back(input);
    else if (is_list_file(path))
      list_file(path, out, missing);
    else if (is_mesh_file(path))
      out.push_back({path, path.lexically_normal().generic_string()});
    else
      throw InvalidArgument(input + ": not a folder, a list file (.txt .lst) or a mesh file (.off .obj .ply .stl)");
  }
  if (!missing.empty()) {
    std::string message = "missing input" + std::string(missing.size() > 1 ? "s" : "") + ":";
    for (const std::string& m : missing) message += "\n  " + m;
    throw InvalidArgument(message);
  }
  std::map<std::string, const MeshInput*> by_name;
  for (const MeshInput& m : out) {
    const auto [at, inserted] = by_name.emplace(m.name, &m);
    if (!inserted)
      throw InvalidArgument("two meshes named '" + m.name + "': " + at->second->path.string() + " and " +
                            m.path.string());
  }
  return out;
}

}  // namespace reebkit

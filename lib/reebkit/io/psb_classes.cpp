#include "reebkit/io/psb_classes.h"

#include "reebkit/core/error.h"

#include <fstream>
#include <sstream>

namespace reebkit {
namespace {

/// The non-blank lines of a file as tokens, with their line numbers.
class LineReader {
 public:
  explicit LineReader(const std::filesystem::path& path) : path_(path), in_(path) {
    if (!in_) throw Error(path.string() + ": cannot open the class file");
  }

  /// The tokens of the next non-blank line; throws when the file ended.
  std::vector<std::string> next(const std::string& expected) {
    std::string line;
    while (std::getline(in_, line)) {
      ++line_;
      std::istringstream words(line);
      std::vector<std::string> tokens;
      for (std::string w; words >> w;) tokens.push_back(w);
      if (!tokens.empty()) return tokens;
    }
    fail("file ends where " + expected + " was expected");
  }

  /// True when only blank lines are left.
  bool at_end() {
    std::string line;
    while (std::getline(in_, line)) {
      ++line_;
      if (line.find_first_not_of(" \t\r") != std::string::npos) return false;
    }
    return true;
  }

  [[noreturn]] void fail(const std::string& problem) const {
    throw Error(path_.string() + ":" + std::to_string(line_) + ": " + problem);
  }

  /// tokens[i] as a count >= 0.
  long count(const std::vector<std::string>& tokens, std::size_t i, const std::string& what) const {
    std::size_t used = 0;
    long value = -1;
    try {
      value = std::stol(tokens[i], &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != tokens[i].size() || value < 0) fail(what + " '" + tokens[i] + "' is not a count");
    return value;
  }

 private:
  std::filesystem::path path_;
  std::ifstream in_;
  int line_ = 0;
};

}  // namespace

std::vector<PsbClass> read_psb_classes(const std::filesystem::path& path) {
  LineReader reader(path);
  const auto magic = reader.next("the header 'PSB 1'");
  if (magic.size() != 2 || magic[0] != "PSB" || magic[1] != "1")
    reader.fail("not a PSB .cla file (expected the header 'PSB 1')");
  const auto counts = reader.next("'<classes> <models>'");
  if (counts.size() != 2) reader.fail("expected '<number of classes> <number of models>'");
  const long classes = reader.count(counts, 0, "number of classes");
  const long models = reader.count(counts, 1, "number of models");

  std::vector<PsbClass> out;
  std::unordered_map<std::string, std::string> seen;  // model -> class
  long listed = 0;
  for (long c = 0; c < classes; ++c) {
    const auto header = reader.next("the header of class " + std::to_string(c + 1) + " of " + std::to_string(classes));
    if (header.size() != 3) reader.fail("expected '<class name> <parent> <number of models>'");
    PsbClass psb{header[0], header[1], {}};
    const long count = reader.count(header, 2, "number of models");
    for (long m = 0; m < count; ++m) {
      const auto model =
          reader.next("model " + std::to_string(m + 1) + " of " + std::to_string(count) + " of class " + psb.name);
      if (model.size() != 1)
        reader.fail("expected one model id (class " + psb.name + " lists " + std::to_string(count) + ")");
      const auto [at, inserted] = seen.emplace(model[0], psb.name);
      if (!inserted) reader.fail("model " + model[0] + " is already in class " + at->second);
      psb.models.push_back(model[0]);
    }
    listed += count;
    out.push_back(std::move(psb));
  }
  if (!reader.at_end()) reader.fail("more lines than the " + std::to_string(classes) + " classes of the header");
  if (listed != models)
    reader.fail("the classes list " + std::to_string(listed) + " models, the header says " + std::to_string(models));
  return out;
}

ClassMap class_map(const std::vector<PsbClass>& classes) {
  ClassMap out;
  for (const PsbClass& c : classes)
    for (const std::string& m : c.models) out.emplace(m, c.name);
  return out;
}

std::string class_of(const ClassMap& classes, const std::string& mesh_name) {
  const std::filesystem::path name(mesh_name);
  for (const std::string& key :
       {mesh_name, std::filesystem::path(name).replace_extension().generic_string(), name.stem().string()}) {
    const auto it = classes.find(key);
    if (it != classes.end()) return it->second;
  }
  return "";
}

}  // namespace reebkit

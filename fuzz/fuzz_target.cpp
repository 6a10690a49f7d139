// libFuzzer entry point for one of reebkit's readers of files made by other
// people's tools. Built once per reader, REEBKIT_FUZZ_READER naming it (see
// fuzz/CMakeLists.txt). A reader may reject its input only with a
// reebkit::Error (whose message names the file and the problem); any other
// exception, a crash, a hang, or a sanitizer report is a bug.
#include "reebkit/core/error.h"
#include "reebkit/evaluation/distance_matrix.h"
#include "reebkit/io/obj.h"
#include "reebkit/io/off.h"
#include "reebkit/io/ply.h"
#include "reebkit/io/psb_classes.h"
#include "reebkit/io/stl.h"
#include "reebkit/mesh/mesh_cleanup.h"
#include "reebkit/store/collection_file.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace {

enum class Reader { Off, Obj, Ply, Stl, Classes, PsbMatrix, ShrecMatrix, Collection };

constexpr Reader kReader = Reader::REEBKIT_FUZZ_READER;

/// The readers of file paths read the input from a file of their own in the
/// temporary folder (one per fuzzing process).
std::filesystem::path input_file(std::string_view bytes, const char* extension) {
  static const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("reebkit-fuzz-" + std::to_string(::getpid()) + extension);
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return path;
}

/// Parses the mesh and cleans it, as load_mesh does after reading.
void clean(const reebkit::PolygonSoup& soup) { reebkit::clean_mesh(soup); }

void read(std::string_view bytes) {
  using namespace reebkit;
  switch (kReader) {
    case Reader::Off: clean(parse_off(bytes, "fuzz.off")); break;
    case Reader::Obj: clean(parse_obj(bytes, "fuzz.obj")); break;
    case Reader::Ply: clean(parse_ply(bytes, "fuzz.ply")); break;
    case Reader::Stl: clean(parse_stl(bytes, "fuzz.stl")); break;
    case Reader::Classes: class_map(read_psb_classes(input_file(bytes, ".cla"))); break;
    case Reader::PsbMatrix: read_distance_matrix(input_file(bytes, ".matrix")); break;  // either, by content
    case Reader::ShrecMatrix: read_shrec_matrix(input_file(bytes, ".txt")); break;
    case Reader::Collection: {
      const CollectionReader reader(input_file(bytes, ".h5"));
      if (reader.size() == 0) break;
      // Each column as a query reads it (alone), then whole.
      (void)reader.name(reader.size() - 1);
      (void)reader.class_label(0);
      (void)reader.find("a");
      (void)reader.class_labels();
      (void)reader.content_hashes();
      (void)reader.entries(0, reader.size());
      break;
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    read(std::string_view(reinterpret_cast<const char*>(data), size));
  } catch (const reebkit::Error&) {
    // A clear rejection: what every reader must do with a bad file.
  }
  return 0;
}

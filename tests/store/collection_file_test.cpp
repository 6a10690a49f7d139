// The HDF5 collection file: round trips field by field, resume, errors, the
// file as h5py + numpy read it, and survival of kill -9 at random moments
// and inside a write.
#include "reebkit/store/collection_file.h"

#include "io/io_test_util.h"
#include "reebkit/core/error.h"
#include "reebkit/io/file_bytes.h"
#include "reebkit/store/write_journal.h"
#include "store/collection_entries.h"
#include "support/test_support.h"

#include <H5Cpp.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <thread>

namespace reebkit {
namespace {

using test::checkpoint_after;
using test::make_entry;
using test::TempDir;
using test::test_provenance;

const char* const kPython = "/usr/bin/python3";

/// Field-by-field equality (doubles bit for bit; a failed entry's signature
/// reads back as NaN).
void expect_same(const GraphRecord& expected, const GraphRecord& actual, const std::string& where) {
  SCOPED_TRACE(where + " entry '" + expected.name + "'");
  EXPECT_EQ(expected.name, actual.name);
  EXPECT_EQ(expected.class_label, actual.class_label);
  EXPECT_EQ(expected.content_hash, actual.content_hash);
  EXPECT_EQ(expected.vertices, actual.vertices);
  EXPECT_EQ(expected.faces, actual.faces);
  EXPECT_EQ(expected.ok, actual.ok);
  EXPECT_EQ(expected.error, actual.error);
  EXPECT_EQ(expected.timings, actual.timings);
  EXPECT_EQ(expected.nodes, actual.nodes);
  EXPECT_EQ(expected.node_geometry, actual.node_geometry);
  EXPECT_EQ(expected.node_attributes, actual.node_attributes);
  EXPECT_EQ(expected.edges, actual.edges);
  EXPECT_EQ(expected.edge_attributes, actual.edge_attributes);
  EXPECT_EQ(expected.feature_points, actual.feature_points);
  // a graph of no nodes (a failed entry) reads back with the offsets {0}
  EXPECT_EQ(expected.skeleton_offset.empty() ? std::vector<std::int64_t>{0} : expected.skeleton_offset,
            actual.skeleton_offset);
  EXPECT_EQ(expected.skeleton_points, actual.skeleton_points);
  if (expected.signature.empty()) {
    ASSERT_EQ(actual.signature.size(), static_cast<std::size_t>(kSignatureLength));
    for (const double s : actual.signature) EXPECT_TRUE(std::isnan(s));
  } else {
    EXPECT_EQ(expected.signature, actual.signature);
  }
}

void write_entries(const std::filesystem::path& path, std::int64_t first, std::int64_t last, bool resume) {
  CollectionWriter writer(path, test_provenance(), resume);
  for (std::int64_t i = first; i < last; ++i) {
    writer.append(make_entry(i));
    if (i % 97 == 13) writer.checkpoint();
  }
  writer.close();
}

/// Reads every entry of `path` and checks it against make_entry.
void expect_entries(const std::filesystem::path& path, std::int64_t count) {
  const CollectionReader reader(path);
  ASSERT_EQ(reader.size(), count);
  // Names and classes one at a time, each read alone (a query's results),
  // before the columns are read whole below.
  for (std::int64_t i = 0; i < count; i += 37) {
    EXPECT_EQ(reader.name(i), make_entry(i).name);
    EXPECT_EQ(reader.class_label(i), make_entry(i).class_label);
  }
  ASSERT_EQ(reader.names().size(), static_cast<std::size_t>(count));
  ASSERT_EQ(reader.signatures().size(), static_cast<std::size_t>(count * kSignatureLength));
  for (std::int64_t i = 0; i < count; ++i) {
    const GraphRecord e = make_entry(i);
    expect_same(e, reader.entry(i), path.filename().string());
    EXPECT_EQ(reader.names()[static_cast<std::size_t>(i)], e.name);
    EXPECT_EQ(reader.class_labels()[static_cast<std::size_t>(i)], e.class_label);
    EXPECT_EQ(reader.find(e.name), i);
    EXPECT_EQ(reader.name(i), e.name);
    EXPECT_EQ(reader.class_label(i), e.class_label);
  }
}

TEST(CollectionFile, RoundTripFieldByField) {
  const TempDir dir;
  // 700 entries: several write batches, chunks and checkpoints.
  write_entries(dir / "c.h5", 0, 700, false);
  expect_entries(dir / "c.h5", 700);
  const CollectionReader reader(dir / "c.h5");
  EXPECT_EQ(reader.find("no such mesh"), std::nullopt);
  EXPECT_EQ(reader.provenance().reebkit_version, REEBKIT_VERSION);
  EXPECT_EQ(reader.provenance().options, test_provenance().options);
  EXPECT_EQ(reader.provenance().command, test_provenance().command);
  // The named options come back typed (in the file's attribute order: by name).
  std::map<std::string, OptionValue> options;
  for (const NamedOption& o : reader.provenance().analysis_options) options.emplace(o.name, o.value);
  EXPECT_EQ(options, (std::map<std::string, OptionValue>{{"epsilon", 0.05},
                                                         {"geodesic", std::string("fmm")},
                                                         {"start_vertex", std::int64_t{-7}}}));
  // The classes in their .cla order, an empty one too.
  ASSERT_EQ(reader.provenance().classes.size(), 3u);
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_EQ(reader.provenance().classes[c].name, test_provenance().classes[c].name);
    EXPECT_EQ(reader.provenance().classes[c].parent, test_provenance().classes[c].parent);
    EXPECT_EQ(reader.provenance().classes[c].models, test_provenance().classes[c].models);
  }
  EXPECT_EQ(reader.provenance().classes_file, test_provenance().classes_file);
  // ISO 8601, UTC: 2024-01-02T03:04:05Z
  EXPECT_EQ(reader.provenance().created.size(), 20u);
  EXPECT_EQ(reader.provenance().created.back(), 'Z');
  EXPECT_THROW(reader.entry(700), InvalidArgument);
  EXPECT_THROW(reader.entry(-1), InvalidArgument);
  EXPECT_THROW(reader.name(700), InvalidArgument);
  EXPECT_THROW(reader.class_label(-1), InvalidArgument);
}

// One pass in batches gives every entry, in order and field by field, for
// batches of one entry, of sizes that do and do not divide the count, and
// larger than the file.
TEST(CollectionFile, ForEachEntryVisitsEveryEntryInOrderWhateverTheBatch) {
  TempDir dir;
  write_entries(dir / "c.h5", 0, 700, false);
  const CollectionReader reader(dir / "c.h5");
  for (const std::int64_t batch : {1, 3, 350, 512, 700, 10000}) {
    std::int64_t next = 0;
    reader.for_each_entry(
        [&](std::int64_t i, const GraphRecord& e) {
          ASSERT_EQ(i, next++);
          expect_same(make_entry(i), e, "batch " + std::to_string(batch));
        },
        EntryParts::Whole, batch);
    EXPECT_EQ(next, 700) << "batch " << batch;
  }
  EXPECT_THROW(reader.for_each_entry([](std::int64_t, const GraphRecord&) {}, EntryParts::Whole, 0), InvalidArgument);
}

// An outline is the entry without its attributes, geometry, skeletons,
// timings and signature: the rest field by field, those left empty.
TEST(CollectionFile, OutlinesAreTheEntriesWithoutTheirAttributes) {
  const TempDir dir;
  write_entries(dir / "c.h5", 0, 300, false);
  const CollectionReader reader(dir / "c.h5");
  std::int64_t seen = 0;
  reader.for_each_entry(
      [&](std::int64_t i, const GraphRecord& outline) {
        ++seen;
        const GraphRecord expected = make_entry(i);
        SCOPED_TRACE("outline " + std::to_string(i));
        EXPECT_EQ(outline.name, expected.name);
        EXPECT_EQ(outline.class_label, expected.class_label);
        EXPECT_EQ(outline.content_hash, expected.content_hash);
        EXPECT_EQ(outline.vertices, expected.vertices);
        EXPECT_EQ(outline.faces, expected.faces);
        EXPECT_EQ(outline.ok, expected.ok);
        EXPECT_EQ(outline.error, expected.error);
        EXPECT_EQ(outline.timings, decltype(outline.timings){});
        EXPECT_EQ(outline.nodes, expected.nodes);
        EXPECT_EQ(outline.edges, expected.edges);
        EXPECT_EQ(outline.feature_points, expected.feature_points);
        EXPECT_TRUE(outline.node_geometry.empty() && outline.node_attributes.empty() &&
                    outline.skeleton_offset.empty() && outline.skeleton_points.empty() &&
                    outline.edge_attributes.empty() && outline.signature.empty());
        EXPECT_EQ(outline.num_nodes(), expected.num_nodes());
        EXPECT_EQ(outline.num_edges(), expected.num_edges());
      },
      EntryParts::Outline, 128);
  EXPECT_EQ(seen, 300);
}

TEST(CollectionFile, EmptyCollection) {
  const TempDir dir;
  CollectionWriter(dir / "c.h5", test_provenance(), false).close();
  const CollectionReader reader(dir / "c.h5");
  EXPECT_EQ(reader.size(), 0);
  EXPECT_TRUE(reader.names().empty());
  EXPECT_TRUE(reader.signatures().empty());
  // No analysis options and one class without models: empty arrays read back.
  Provenance bare;
  bare.classes = {{"none", "0", {}}};
  CollectionWriter(dir / "bare.h5", bare, false).close();
  const CollectionReader bare_reader(dir / "bare.h5");
  EXPECT_TRUE(bare_reader.provenance().analysis_options.empty());
  ASSERT_EQ(bare_reader.provenance().classes.size(), 1u);
  EXPECT_EQ(bare_reader.provenance().classes[0].name, "none");
  EXPECT_TRUE(bare_reader.provenance().classes[0].models.empty());
}

TEST(CollectionFile, ResumeKeepsOldEntriesAndAppends) {
  const TempDir dir;
  write_entries(dir / "c.h5", 0, 300, false);
  {
    CollectionWriter writer(dir / "c.h5", test_provenance(), true);
    ASSERT_EQ(writer.existing().size(), 300u);
    for (std::int64_t i = 0; i < 300; ++i) {
      EXPECT_EQ(writer.existing()[static_cast<std::size_t>(i)].first, make_entry(i).name);
      EXPECT_EQ(writer.existing()[static_cast<std::size_t>(i)].second, make_entry(i).content_hash);
    }
    EXPECT_EQ(writer.size(), 300);
    for (std::int64_t i = 300; i < 420; ++i) writer.append(make_entry(i));
    EXPECT_EQ(writer.size(), 420);
  }  // the destructor checkpoints
  expect_entries(dir / "c.h5", 420);
  EXPECT_FALSE(std::filesystem::exists(dir / "c.h5.resume-tmp"));
  // Resuming a file that does not exist starts a new one.
  CollectionWriter fresh(dir / "new.h5", test_provenance(), true);
  EXPECT_TRUE(fresh.existing().empty());
}

TEST(CollectionFile, ReplacesAnExistingFileWithoutResume) {
  const TempDir dir;
  write_entries(dir / "c.h5", 0, 50, false);
  write_entries(dir / "c.h5", 0, 7, false);
  expect_entries(dir / "c.h5", 7);
}

TEST(CollectionFile, ErrorsNameTheFile) {
  const TempDir dir;
  const auto contains = [](const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
  };
  const auto missing = dir / "missing.h5";
  EXPECT_TRUE(contains(test::thrown_message<Error>([&] { CollectionReader r(missing); }), missing.string()));

  const auto text = dir / "text.h5";
  test::write_bytes(text, "not HDF5 at all\n");
  const std::string not_hdf5 = test::thrown_message<Error>([&] { CollectionReader r(text); });
  EXPECT_TRUE(contains(not_hdf5, text.string()) && contains(not_hdf5, "not an HDF5 file")) << not_hdf5;
  EXPECT_TRUE(
      contains(test::thrown_message<Error>([&] { CollectionWriter w(text, test_provenance(), true); }), text.string()));

  const auto other = dir / "other.h5";
  {
    H5::H5File file(other.string(), H5F_ACC_TRUNC);
    const hsize_t dims[1] = {3};
    file.createDataSet("data", H5::PredType::NATIVE_INT, H5::DataSpace(1, dims));
  }
  const std::string no_layout = test::thrown_message<Error>([&] { CollectionReader r(other); });
  EXPECT_TRUE(contains(no_layout, other.string()) && contains(no_layout, "not a reebkit collection")) << no_layout;

  // The previous layout (3: before the pose-invariant attribute columns) and a future one.
  for (const int version : {kCollectionLayoutVersion - 1, kCollectionLayoutVersion + 1}) {
    const auto other_layout = dir / ("layout" + std::to_string(version) + ".h5");
    write_entries(other_layout, 0, 3, false);
    {
      H5::H5File file(other_layout.string(), H5F_ACC_RDWR);
      file.openAttribute("layout").write(H5::PredType::NATIVE_INT, &version);
    }
    const std::string layout = test::thrown_message<Error>([&] { CollectionReader r(other_layout); });
    EXPECT_TRUE(contains(layout, other_layout.string()) &&
                contains(layout, "layout version " + std::to_string(version)) &&
                contains(layout, "re-index the meshes with this version"))
        << layout;
  }

  const auto unwritable = dir / "no_such_folder" / "c.h5";
  EXPECT_TRUE(contains(test::thrown_message<Error>([&] { CollectionWriter w(unwritable, test_provenance(), false); }),
                       unwritable.string()));
}

TEST(CollectionFile, CorruptedFilesFoundByTheFuzzerFailAtOnceNamingTheFile) {
  // Regressions of fuzz_collection: a hang (HDF5 retried SWMR metadata reads
  // for minutes; the test's timeout catches one) and an error path of HDF5.
  for (const char* name : {"store/corrupted_metadata.h5", "store/corrupted_superblock.h5"}) {
    const std::filesystem::path path = test::fixture(name);
    ASSERT_TRUE(std::filesystem::is_regular_file(path)) << path;
    const std::string message = test::thrown_message<Error>([&] {
      const CollectionReader reader(path);
      (void)reader.entries(0, reader.size());
    });
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
  }
}

TEST(CollectionFile, RejectsInconsistentEntries) {
  const TempDir dir;
  CollectionWriter writer(dir / "c.h5", test_provenance(), false);
  GraphRecord e = make_entry(1);
  e.node_attributes.pop_back();
  EXPECT_THROW(writer.append(e), InvalidArgument);
  e = make_entry(1);
  e.edges[0] = e.num_nodes();
  EXPECT_THROW(writer.append(e), InvalidArgument);
  e = make_entry(1);
  e.skeleton_points.push_back(0.0);
  EXPECT_THROW(writer.append(e), InvalidArgument);
  EXPECT_EQ(writer.size(), 0);
  writer.close();
  EXPECT_THROW(writer.append(make_entry(0)), InvalidArgument);
}

// --- The file as Python reads it ---------------------------------------------

/// Reads a collection with h5py + numpy only (the README snippet, plus checks
/// of the CSR invariants), and prints every committed entry, one field per
/// line: "<i>/<field>\t<values...>".
const char* const kPythonReader = R"PY(
import sys
import h5py
import numpy as np

out = sys.stdout.buffer
def emit(key, values):
    out.write(("\t".join([key] + [repr(v) if isinstance(v, float) else str(v) for v in values]) + "\n").encode())

def text(f, key, G):                            # a text column: UTF-8 bytes + offsets
    offset = f[key + "_offset"][:G + 1]
    data = f[key][:offset[G]].tobytes()
    return [data[offset[i]:offset[i + 1]].decode() for i in range(G)]

def decode(value):                              # string attributes are fixed-length UTF-8 bytes
    if isinstance(value, bytes):
        return value.decode()
    return [v.decode() for v in value] if isinstance(value, np.ndarray) and value.dtype.kind == "S" else value

# swmr=True also opens a file whose writer was killed (README).
with h5py.File(sys.argv[1], "r", libver="latest", swmr=True) as f:
    G = int(f["count"][0])                      # trust only the committed entries
    emit("layout", [int(f.attrs["layout"])])
    emit("command", [f.attrs["command"].decode()])
    for key, value in sorted(f["analysis_options"].attrs.items()):
        value = decode(value.item() if hasattr(value, "item") else value)
        emit("analysis_options/" + key, [type(value).__name__, value])
    classes = {key: decode(value) for key, value in f["classes"].attrs.items()}
    offset, model = classes["model_offset"], classes["model"]
    for c, name in enumerate(classes["name"]):
        emit("classes/" + name, [classes["parent"][c]] + list(model[offset[c]:offset[c + 1]]))
    emit("classes_file", [classes["file"]])
    emit("count", [G])
    for key in ("timings", "signature", "nodes", "node_geometry", "node_attr", "edges", "edge_attr", "skeleton_points"):
        emit("columns/" + key, decode(f[key].attrs["columns"]))
    name, cls, error = (text(f, key, G) for key in ("name", "class", "error"))
    status, hashes = f["status"][:G], f["content_hash"][:G]
    vertices, faces, timings, signature = f["vertices"][:G], f["faces"][:G], f["timings"][:G], f["signature"][:G]
    node_offset, edge_offset, feature_offset = (f[k][:G + 1] for k in ("node_offset", "edge_offset", "feature_offset"))
    N, E, F = node_offset[G], edge_offset[G], feature_offset[G]
    nodes, node_geometry, node_attr = f["nodes"][:N], f["node_geometry"][:N], f["node_attr"][:N]
    skeleton_offset = f["skeleton_offset"][:N + 1]
    skeleton_points = f["skeleton_points"][:skeleton_offset[N]]
    edges, edge_attr, feature_points = f["edges"][:E], f["edge_attr"][:E], f["feature_points"][:F]

for o in (node_offset, edge_offset, feature_offset, skeleton_offset):
    assert o[0] == 0 and np.all(np.diff(o) >= 0)
for i in range(G):
    n0, n1 = node_offset[i], node_offset[i + 1]
    e0, e1 = edge_offset[i], edge_offset[i + 1]
    assert np.all((edges[e0:e1] >= 0) & (edges[e0:e1] < n1 - n0))  # node ids local to the graph
    assert status[i] in (0, 1) and (status[i] == 0 or n1 == n0)
    s0, s1 = skeleton_offset[n0], skeleton_offset[n1]
    for key, values in (("name", [name[i]]), ("class", [cls[i]]), ("error", [error[i]]), ("status", [status[i]]),
                        ("hash", [hashes[i]]), ("vertices", [vertices[i]]), ("faces", [faces[i]]),
                        ("timings", timings[i]), ("signature", signature[i]), ("nodes", nodes[n0:n1].ravel()),
                        ("node_geometry", node_geometry[n0:n1].ravel()), ("node_attr", node_attr[n0:n1].ravel()),
                        ("edges", edges[e0:e1].ravel()), ("edge_attr", edge_attr[e0:e1].ravel()),
                        ("features", feature_points[feature_offset[i]:feature_offset[i + 1]]),
                        ("skeleton_offset", skeleton_offset[n0:n1 + 1] - s0),
                        ("skeleton_points", skeleton_points[s0:s1].ravel())):
        emit("%d/%s" % (i, key), [v.item() if hasattr(v, "item") else v for v in values])
)PY";

bool python_has_h5py() {
  if (!std::filesystem::exists(kPython)) return false;
  return std::system((std::string(kPython) + " -c 'import h5py, numpy' 2>/dev/null").c_str()) == 0;
}

/// Python's output, as key -> tab-separated values.
std::map<std::string, std::vector<std::string>> read_with_python(const std::filesystem::path& path) {
  const std::filesystem::path script = path.parent_path() / "read_collection.py";
  test::write_bytes(script, kPythonReader);
  const std::string command = std::string(kPython) + " '" + script.string() + "' '" + path.string() + "' 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  std::string output;
  char buffer[4096];
  while (pipe != nullptr && std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  const int status = pipe != nullptr ? ::pclose(pipe) : -1;
  EXPECT_EQ(status, 0) << output;
  std::map<std::string, std::vector<std::string>> fields;
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    std::vector<std::string> parts;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, '\t');) parts.push_back(cell);
    if (parts.empty()) continue;
    const std::string key = parts.front();
    fields[key] = std::vector<std::string>(parts.begin() + 1, parts.end());
  }
  return fields;
}

template <typename T>
std::vector<T> parse(const std::vector<std::string>& cells) {
  std::vector<T> out;
  for (const std::string& c : cells) {
    if constexpr (std::is_floating_point_v<T>)
      out.push_back(std::stod(c));
    else
      out.push_back(static_cast<T>(std::stoll(c)));
  }
  return out;
}

/// Entry i as Python printed it.
GraphRecord entry_from_python(const std::map<std::string, std::vector<std::string>>& fields, std::int64_t i) {
  const auto field = [&](const std::string& key) -> const std::vector<std::string>& {
    static const std::vector<std::string> none;
    const auto it = fields.find(std::to_string(i) + "/" + key);
    return it == fields.end() ? none : it->second;
  };
  const auto one = [&](const std::string& key) { return field(key).empty() ? std::string() : field(key).front(); };
  GraphRecord e;
  e.name = one("name");
  e.class_label = one("class");
  e.error = one("error");
  e.ok = one("status") == "0";
  e.content_hash = std::stoull(one("hash"));
  e.vertices = std::stoll(one("vertices"));
  e.faces = std::stoll(one("faces"));
  const auto timings = parse<double>(field("timings"));
  std::copy_n(timings.begin(), std::min<std::size_t>(timings.size(), kTimeColumnCount), e.timings.begin());
  e.signature = parse<double>(field("signature"));
  e.nodes = parse<std::int32_t>(field("nodes"));
  e.node_geometry = parse<double>(field("node_geometry"));
  e.node_attributes = parse<double>(field("node_attr"));
  e.edges = parse<std::int32_t>(field("edges"));
  e.edge_attributes = parse<double>(field("edge_attr"));
  e.feature_points = parse<std::int32_t>(field("features"));
  e.skeleton_offset = parse<std::int64_t>(field("skeleton_offset"));
  e.skeleton_points = parse<double>(field("skeleton_points"));
  return e;
}

void expect_python_reads(const std::filesystem::path& path, std::int64_t count) {
  const auto fields = read_with_python(path);
  ASSERT_EQ(fields.count("count"), 1u);
  ASSERT_EQ(fields.at("count"), std::vector<std::string>{std::to_string(count)});
  for (std::int64_t i = 0; i < count; ++i) {
    expect_same(make_entry(i), entry_from_python(fields, i), "python");
  }
}

TEST(CollectionFile, PythonReadsItWithH5pyAndNumpy) {
  if (!python_has_h5py()) GTEST_SKIP() << kPython << " with h5py and numpy not found";
  const TempDir dir;
  write_entries(dir / "c.h5", 0, 40, false);
  expect_python_reads(dir / "c.h5", 40);
  const auto fields = read_with_python(dir / "c.h5");
  EXPECT_EQ(fields.at("layout"), std::vector<std::string>{std::to_string(kCollectionLayoutVersion)});
  EXPECT_EQ(fields.at("command"), std::vector<std::string>{test_provenance().command});
  // Typed analysis options: h5py gives float, int and (fixed-length strings) bytes, decoded to str.
  EXPECT_EQ(fields.at("analysis_options/epsilon"), (std::vector<std::string>{"float", "0.05"}));
  EXPECT_EQ(fields.at("analysis_options/geodesic"), (std::vector<std::string>{"str", "fmm"}));
  EXPECT_EQ(fields.at("analysis_options/start_vertex"), (std::vector<std::string>{"int", "-7"}));
  EXPECT_EQ(fields.at("classes/star"), (std::vector<std::string>{"0", "m2", "m10", "m1"}));
  EXPECT_EQ(fields.at("classes/empty"), (std::vector<std::string>{"star"}));
  EXPECT_EQ(fields.at("classes/torus «ring»"), (std::vector<std::string>{"0", "m6"}));
  EXPECT_EQ(fields.at("classes_file"), std::vector<std::string>{test_provenance().classes_file});
  const auto names = [](const auto& array) { return std::vector<std::string>(array.begin(), array.end()); };
  EXPECT_EQ(fields.at("columns/node_attr"), names(kNodeAttributeNames));
  EXPECT_EQ(fields.at("columns/edge_attr"), names(kEdgeAttributeNames));
  EXPECT_EQ(fields.at("columns/signature"), names(kSignatureNames));
  EXPECT_EQ(fields.at("columns/nodes").size(), static_cast<std::size_t>(kNodeColumnCount));
  EXPECT_EQ(fields.at("columns/node_geometry").size(), static_cast<std::size_t>(kGeomColumnCount));
  EXPECT_EQ(fields.at("columns/timings").size(), static_cast<std::size_t>(kTimeColumnCount));
  EXPECT_EQ(fields.at("columns/edges").size(), 2u);
  EXPECT_EQ(fields.at("columns/skeleton_points").size(), 3u);
}

/// A dataset's element type as the docs write it: "uint8", "int64", "float64".
std::string type_name(const H5::DataSet& dataset) {
  const std::string bits = std::to_string(8 * dataset.getDataType().getSize());
  if (dataset.getTypeClass() == H5T_FLOAT) return "float" + bits;
  return (dataset.getIntType().getSign() == H5T_SGN_NONE ? "uint" : "int") + bits;
}

// Before: docs/collection-file.md gave signature 64 columns and node_attr
// 34, where the file has 80 and 40.
TEST(CollectionFile, TheDocsTableOfDatasetsIsTheFileDatasetByDataset) {
  const TempDir dir;
  write_entries(dir / "c.h5", 0, 40, false);
  // Each dataset as "(, width) type" (rank 2) or "(,) type" (rank 1).
  const auto shape = [](const std::string& width, const std::string& type) {
    return (width.empty() ? "(,)" : "(, " + width + ")") + " " + type;
  };
  std::map<std::string, std::string> file;
  const H5::H5File h5((dir / "c.h5").string(), H5F_ACC_RDONLY);
  for (hsize_t i = 0; i < h5.getNumObjs(); ++i) {
    const std::string name = h5.getObjnameByIdx(i);
    if (h5.childObjType(name) != H5O_TYPE_DATASET) continue;
    const H5::DataSet dataset = h5.openDataSet(name);
    hsize_t dims[2] = {0, 0};
    const int rank = dataset.getSpace().getSimpleExtentDims(dims);
    file[name] = shape(rank == 2 ? std::to_string(dims[1]) : "", type_name(dataset));
  }
  // The table's rows: "| `a`, `b` | (G,) int64, (G+1,) int64 | meaning |",
  // one shape for all the names or one each.
  std::ifstream in(std::string(REEBKIT_SOURCE_DIR) + "/docs/collection-file.md");
  ASSERT_TRUE(in) << "cannot read docs/collection-file.md";
  const std::regex name_pattern("`([a-z_]+)`"), shape_pattern(R"(\(([^,)]*),\s*([^)]*)\)\s+(\w+))");
  std::map<std::string, std::string> docs;
  for (std::string line; std::getline(in, line) && line.rfind("Every 2-D dataset", 0) != 0;) {
    if (line.rfind("| `", 0) != 0) continue;
    const std::size_t bar = line.find(" | "), next = line.find(" | ", bar + 3);
    const std::string names_cell = line.substr(0, bar), shapes_cell = line.substr(bar + 3, next - bar - 3);
    std::vector<std::string> names, shapes;
    for (std::sregex_iterator m(names_cell.begin(), names_cell.end(), name_pattern), end; m != end; ++m)
      names.push_back((*m)[1]);
    for (std::sregex_iterator m(shapes_cell.begin(), shapes_cell.end(), shape_pattern), end; m != end; ++m)
      shapes.push_back(shape((*m)[2], (*m)[3]));
    ASSERT_TRUE(shapes.size() == 1 || shapes.size() == names.size()) << line;
    for (std::size_t k = 0; k < names.size(); ++k) docs[names[k]] = shapes[shapes.size() == 1 ? 0 : k];
  }
  EXPECT_EQ(docs, file) << "docs/collection-file.md's table of datasets and the file written disagree";
}

// --- kill -9 ----------------------------------------------------------------

/// A running tests/store/crash_writer: its pid and the read end of its
/// stdout, where it reports each committed count.
struct CrashWriter {
  pid_t pid = -1;
  int reports = -1;
};

/// Starts tests/store/crash_writer on `path`, with `environment` ("NAME=value")
/// added to this process's.
CrashWriter start_crash_writer(const std::filesystem::path& path, const std::vector<std::string>& environment) {
  int fds[2];
  if (::pipe(fds) != 0) return {};
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(fds[1], 1);
    ::close(fds[0]);
    ::close(fds[1]);
    for (const std::string& variable : environment) ::putenv(::strdup(variable.c_str()));
    ::execl(CRASH_WRITER, CRASH_WRITER, path.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(fds[1]);
  return {pid, fds[0]};
}

/// Waits for the writer to end; returns the last count it reported (-1: it
/// ended before the file was set up) and its wait status.
std::pair<std::int64_t, int> finish(const CrashWriter& writer) {
  int status = 0;
  ::waitpid(writer.pid, &status, 0);
  std::int64_t reported = -1;
  for (std::int64_t c = 0; ::read(writer.reports, &c, sizeof c) == sizeof c;) reported = c;
  ::close(writer.reports);
  return {reported, status};
}

/// Checks the file a crash writer left after reporting `reported` entries:
/// it holds them, or the next checkpoint too if the writer died between
/// committing it and reporting it, every entry whole; and a resume drops
/// anything past it and appends after it. Returns the entry count.
std::int64_t expect_last_checkpoint_then_resume(const std::filesystem::path& path, std::int64_t reported, bool python,
                                                bool resume = true) {
  std::int64_t next = reported;
  while (!checkpoint_after(next)) ++next;
  const std::int64_t count = CollectionReader(path).size();
  EXPECT_TRUE(count == reported || count == next + 1) << count << " entries, reported " << reported;
  expect_entries(path, count);
  if (python) expect_python_reads(path, count);
  if (!resume) return count;
  {
    CollectionWriter writer(path, test_provenance(), true);
    EXPECT_EQ(static_cast<std::int64_t>(writer.existing().size()), count);
    writer.append(make_entry(count));
  }
  EXPECT_FALSE(std::filesystem::exists(journal_path(path)));  // closed whole
  expect_entries(path, count + 1);
  return count;
}

TEST(CollectionFile, SurvivesKillMinus9AtRandomMoments) {
  const TempDir dir;
  const bool python = python_has_h5py();
  std::mt19937 rng(20240611);
  int trials_with_entries = 0;
  for (int trial = 0; trial < 10; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const auto path = dir / ("crash" + std::to_string(trial) + ".h5");
    const CrashWriter writer = start_crash_writer(path, {});
    ASSERT_GT(writer.pid, 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(std::uniform_int_distribution<int>(30, 600)(rng)));
    ::kill(writer.pid, SIGKILL);
    const auto [reported, status] = finish(writer);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the writer stopped by itself, status " << status;
    if (reported < 0) continue;  // killed before the file was set up
    trials_with_entries += expect_last_checkpoint_then_resume(path, reported, python && trial < 3) > 0;
  }
  EXPECT_GE(trials_with_entries, 5);
}

// A process killed inside a write leaves it torn at a page boundary (see
// store/write_journal.h): here at every third write of the first six or so
// checkpoints, the file's and the journal's alike. Before the journal, a
// dataset torn so no longer opened ("H5Dopen2 failed") or read, about twice
// per checkpoint of this writer; a kill -9 at a random moment tore one in
// about a thousand runs.
TEST(CollectionFile, AWriteTornByADyingWriterIsCompletedFromItsJournal) {
  const TempDir dir;
  std::string asan_options = std::getenv("ASAN_OPTIONS") != nullptr ? std::getenv("ASAN_OPTIONS") : "";
  asan_options += std::string(asan_options.empty() ? "" : ":") + "verify_asan_link_order=0";  // the library comes first
  int completed = 0;
  for (int k = 1; k <= 600; k += 3) {
    SCOPED_TRACE("write " + std::to_string(k) + " torn");
    const auto path = dir / ("torn" + std::to_string(k) + ".h5");
    const CrashWriter writer =
        start_crash_writer(path, {"LD_PRELOAD=" TEAR_WRITE_LIBRARY, "TEAR_WRITE_AT=" + std::to_string(k),
                                  "ASAN_OPTIONS=" + asan_options});
    ASSERT_GT(writer.pid, 0);
    const auto [reported, status] = finish(writer);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 9) << "status " << status;
    if (reported < 0) continue;  // torn before the file was set up
    completed += std::filesystem::exists(journal_path(path)) && complete_interrupted_write(path);
    expect_last_checkpoint_then_resume(path, reported, false, k % 30 == 1);
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(completed, 50) << completed;  // most torn writes had a whole record
}

TEST(CollectionFile, AFailedWriteGivesOneErrorKeepsTheLastCheckpointAndExitsCleanly) {
  // A file size limit fails the writes as a full disk does. Before: the
  // error, a "DataSet::~DataSet - H5Dclose failed" line per dataset, then a
  // segfault at exit in H5close.
  const TempDir dir;
  const auto path = dir / "full.h5";
  const auto [status, output] = test::run_with_file_size_limit(256 * 1024, [&](int fd) {
    std::int64_t committed = 0;
    std::string message = "no error";
    try {
      CollectionWriter writer(path, test_provenance(), false);
      for (std::int64_t i = 0; i < 100000; ++i) {
        writer.append(make_entry(i));
        if (i % 5 == 4) {
          writer.checkpoint();
          committed = i + 1;
        }
      }
    } catch (const Error& e) {
      message = e.what();
    }
    const std::string report = std::to_string(committed) + "\n" + message + "\n";
    (void)!::write(fd, report.data(), report.size());
  });
  EXPECT_EQ(status, 0) << output;  // exit() ran HDF5's cleanup without crashing
  std::istringstream lines(output);
  std::int64_t committed = -1;
  lines >> committed;
  EXPECT_GT(committed, 0) << output;
  EXPECT_NE(output.find(path.string() + ": writing: File too large (HDF5: "), std::string::npos) << output;
  EXPECT_EQ(output.find("H5Dclose"), std::string::npos) << output;
  EXPECT_EQ(output.find("HDF5-DIAG"), std::string::npos) << output;
  // The file holds the last checkpoint (or the one that failed, when only its
  // last flush did), every entry read back.
  const std::int64_t count = CollectionReader(path).size();
  EXPECT_TRUE(count == committed || count == committed + 5) << count << " entries, committed " << committed;
  expect_entries(path, count);
}

TEST(CollectionFile, VerbosePrintsTheHdf5ErrorStack) {
  const TempDir dir;
  const auto path = dir / "full.h5";
  const auto [status, output] = test::run_with_file_size_limit(64 * 1024, [&](int fd) {
    print_hdf5_error_stacks(true);
    try {
      CollectionWriter writer(path, test_provenance(), false);
      for (std::int64_t i = 0; i < 100000; ++i) writer.append(make_entry(i));
    } catch (const Error& e) {
      (void)!::write(fd, e.what(), std::strlen(e.what()));
    }
  });
  EXPECT_EQ(status, 0) << output;
  EXPECT_NE(output.find("File too large"), std::string::npos) << output;
  EXPECT_NE(output.find("HDF5-DIAG"), std::string::npos) << output;
}

/// The byte ranges [first, last) of the chunks of the datasets `names` in
/// the collection file `path`, as stored (compressed).
std::vector<std::pair<std::size_t, std::size_t>> chunk_ranges(const std::filesystem::path& path,
                                                              const std::vector<std::string>& names) {
  std::vector<std::pair<std::size_t, std::size_t>> ranges;
  const H5::H5File file(path.string(), H5F_ACC_RDONLY);
  for (const std::string& name : names) {
    const H5::DataSet dataset = file.openDataSet(name);
    const H5::DataSpace space = dataset.getSpace();
    hsize_t chunks = 0;
    EXPECT_GE(H5Dget_num_chunks(dataset.getId(), space.getId(), &chunks), 0) << name;
    for (hsize_t k = 0; k < chunks; ++k) {
      haddr_t address = 0;
      hsize_t size = 0;
      EXPECT_GE(H5Dget_chunk_info(dataset.getId(), space.getId(), k, nullptr, nullptr, &address, &size), 0) << name;
      ranges.emplace_back(static_cast<std::size_t>(address), static_cast<std::size_t>(address + size));
    }
  }
  return ranges;
}

TEST(CollectionFile, AFlippedByteAnywhereIsReadOrAClearError) {
  // One byte inverted in turn, at 400 places spread over a small collection
  // and at every byte of the chunks holding its strings and their offsets:
  // the file reads (the byte was in data no check covers) or throws Error
  // naming the file; nothing else escapes, nothing crashes, nothing hangs.
  // Before layout 4 the strings were variable-length, in HDF5's global heap
  // ("GCOL"), which HDF5 1.10 reads trusting the stored lengths: one flipped
  // byte there crashed (H5HG_read) or hung the reader.
  const TempDir dir;
  write_entries(dir / "c.h5", 0, 24, false);
  const std::string bytes = read_file_bytes(dir / "c.h5");
  EXPECT_EQ(bytes.find("GCOL"), std::string::npos) << "the file has a global heap";
  std::set<std::size_t> places;
  const std::size_t step = bytes.size() / 400 + 1;
  for (std::size_t at = 0; at < bytes.size(); at += step) places.insert(at);
  std::size_t text_bytes = 0;
  for (const auto& [first, last] :
       chunk_ranges(dir / "c.h5", {"name", "name_offset", "class", "class_offset", "error", "error_offset"})) {
    ASSERT_LE(last, bytes.size());
    for (std::size_t at = first; at < last; ++at) places.insert(at);
    text_bytes += last - first;
  }
  EXPECT_GT(text_bytes, 0u);
  int read = 0, refused = 0;
  const auto path = dir / "damaged.h5";
  for (const std::size_t at : places) {
    std::string damaged = bytes;
    damaged[at] = static_cast<char>(~damaged[at]);
    test::write_bytes(path, damaged);
    try {
      const CollectionReader reader(path);
      (void)reader.entries(0, reader.size());
      ++read;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << "byte " << at << ": " << e.what();
      ++refused;
    }
  }
  EXPECT_GT(refused, 0);
  std::printf("%zu bytes (%zu in the chunks of the text columns): %zu flipped in turn, %d read, %d refused\n",
              bytes.size(), text_bytes, places.size(), read, refused);
}

TEST(CollectionFile, OffsetsAndCountPastTheDataAreAClearError) {
  // Offsets are checked before they size anything: a count or an offset
  // pointing past the rows written is refused naming the file and the dataset.
  const TempDir dir;
  const auto damage = [&](const char* dataset, hsize_t row, std::int64_t value) {
    const auto path = dir / (std::string(dataset) + ".h5");
    write_entries(path, 0, 5, false);
    {
      H5::H5File file(path.string(), H5F_ACC_RDWR);
      H5::DataSet d = file.openDataSet(dataset);
      H5::DataSpace space = d.getSpace();
      const hsize_t one[1] = {1}, at[1] = {row};
      space.selectHyperslab(H5S_SELECT_SET, one, at);
      d.write(&value, H5::PredType::NATIVE_INT64, H5::DataSpace(1, one), space);
    }
    return test::thrown_message<Error>([&] {
      const CollectionReader reader(path);
      (void)reader.entries(0, reader.size());
    });
  };
  for (const std::int64_t count : {std::int64_t{-1}, std::int64_t{6}, std::int64_t{1} << 60}) {
    const std::string message = damage("count", 0, count);
    EXPECT_NE(message.find("count.h5"), std::string::npos) << message;
    EXPECT_NE(message.find("count (" + std::to_string(count) + ") exceeds the rows written"), std::string::npos)
        << message;
  }
  for (const char* offsets : {"name_offset", "class_offset", "error_offset", "node_offset", "skeleton_offset"}) {
    for (const std::int64_t value : {std::int64_t{-5}, std::int64_t{1} << 50}) {
      const std::string message = damage(offsets, 3, value);
      EXPECT_NE(message.find(std::string(offsets) + ".h5"), std::string::npos) << message;
      EXPECT_NE(message.find(std::string(offsets) + " decreases or points past its data"), std::string::npos)
          << message;
    }
  }
}

}  // namespace
}  // namespace reebkit

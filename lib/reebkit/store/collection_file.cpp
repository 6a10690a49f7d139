// The HDF5 collection file: flat, extendible datasets with CSR offsets
// (docs/collection-file.md).
//
// Crash consistency. The file is written in HDF5's single-writer /
// multiple-reader (SWMR) mode (HDF5 >= 1.10, latest file format): the library
// orders its metadata writes so that the file on disk is a coherent HDF5
// file between any two of its writes; a write the process is killed inside
// is completed from the write journal (store/write_journal.h) when the file
// is next opened. On top of that,
// reebkit commits entries in two phases:
//   1. append the rows of every dataset, H5Fflush, fsync;
//   2. write the entry count into the one-element dataset `count`, H5Fflush,
//      fsync.
// Readers trust only the first `count` entries (and the offsets up to them),
// so rows written after the last commit are ignored. Freed file space is
// never reused (file space strategy NONE): a chunk that is rewritten because
// rows were added to it moves to a new address, and the old copy, which the
// last commit still refers to, stays intact until the file is closed. A
// crashed file keeps SWMR's "open for writing" mark in its superblock: HDF5
// then opens it for reading only in SWMR read mode (CollectionReader falls
// back to it; h5py: swmr=True), and resume rewrites the committed entries
// into a fresh file (temp file + rename), which also drops the rows past
// `count` and the space wasted by moved chunks.
#include "reebkit/store/collection_file.h"

#include "reebkit/core/error.h"
#include "reebkit/store/write_journal.h"

#include <H5Cpp.h>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <functional>
#include <limits>
#include <new>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <thread>
#include <type_traits>
#include <unordered_map>

namespace reebkit {
namespace {

namespace fs = std::filesystem;

constexpr std::array<const char*, kNodeColumnCount> kNodeColumnNames = {"type", "end", "birth_vertex", "vertex_count"};
constexpr std::array<const char*, kGeomColumnCount> kGeomColumnNames = {"area",         "fq_min",       "fq_max",
                                                                        "barycenter_x", "barycenter_y", "barycenter_z"};
constexpr std::array<const char*, kTimeColumnCount> kTimeColumnNames = {"load_ms",     "graph_ms", "features_ms",
                                                                        "quotient_ms", "reeb_ms",  "attributes_ms"};
constexpr std::array<const char*, 2> kEdgeColumnNames = {"earlier_node", "later_node"};
constexpr std::array<const char*, 3> kPointColumnNames = {"x", "y", "z"};

/// Uncompressed bytes per chunk: small enough that rewriting the last,
/// partly filled chunk of every dataset at each commit stays cheap.
constexpr hsize_t kChunkBytes = 16 * 1024;
constexpr int kDeflateLevel = 4;
/// Buffered entries written to the datasets (without committing them) when
/// this many are pending, so that memory stays bounded between checkpoints.
constexpr std::size_t kBatchEntries = 256;

/// Fixed-length UTF-8 strings of `width` bytes, padded with NULs: the type
/// of every string attribute. No string in the file is variable-length:
/// HDF5 keeps those in its global heap, which HDF5 1.10 reads trusting the
/// stored lengths (one damaged byte there crashed or hung readers), where
/// an attribute's bytes sit in its object header, under its checksum.
H5::StrType text_type(std::size_t width) {
  H5::StrType type(H5::PredType::C_S1, std::max<std::size_t>(width, 1));
  type.setStrpad(H5T_STR_NULLPAD);
  type.setCset(H5T_CSET_UTF8);
  return type;
}

[[noreturn]] void fail(const fs::path& path, const std::string& problem) {
  throw Error(path.string() + ": " + problem);
}

/// Whether a failure also prints HDF5's error stack (print_hdf5_error_stacks).
std::atomic<bool> print_error_stacks{false};

/// The system's reason for the first HDF5 failure in a guarded() call (e.g.
/// "No space left on device"), as its error stack recorded it when it
/// failed; "" when none.
/// Taken then, because the C++ wrappers' destructors make HDF5 calls that
/// clear the stack before a caller sees the exception.
thread_local std::string last_system_reason;

herr_t on_hdf5_failure(hid_t stack, void*) {
  if (print_error_stacks) H5Eprint2(stack, stderr);
  H5Ewalk2(
      stack, H5E_WALK_DOWNWARD,
      [](unsigned, const H5E_error2_t* error, void*) -> herr_t {
        const std::string description = error->desc != nullptr ? error->desc : "";
        const std::string marker = "error message = '";
        const auto at = description.find(marker);
        if (at != std::string::npos && last_system_reason.empty())
          last_system_reason =
              description.substr(at + marker.size(), description.find('\'', at + marker.size()) - at - marker.size());
        return 0;
      },
      nullptr);
  return 0;
}

/// While alive, HDF5 calls on_hdf5_failure when a call fails (instead of
/// nothing: the library is kept quiet otherwise, H5::Exception::dontPrint,
/// also when it cannot close a damaged file at exit).
class FailureWatch {
 public:
  FailureWatch() {
    H5Eget_auto2(H5E_DEFAULT, &previous_, &previous_data_);
    H5Eset_auto2(H5E_DEFAULT, on_hdf5_failure, nullptr);
    last_system_reason.clear();
  }
  ~FailureWatch() { H5Eset_auto2(H5E_DEFAULT, previous_, previous_data_); }
  FailureWatch(const FailureWatch&) = delete;
  FailureWatch& operator=(const FailureWatch&) = delete;

 private:
  H5E_auto2_t previous_ = nullptr;
  void* previous_data_ = nullptr;
};

/// Runs `body`, turning HDF5's exceptions into one Error naming the file,
/// what was being done and the system's reason when there is one.
template <typename Body>
auto guarded(const fs::path& path, const char* doing, Body&& body) {
  const FailureWatch watch;
  try {
    return body();
  } catch (const H5::Exception& e) {
    const std::string reason = last_system_reason;
    const std::string hdf5 = "HDF5: " + e.getFuncName() + ": " + e.getDetailMsg();
    fail(path, std::string(doing) + ": " + (reason.empty() ? hdf5 : reason + " (" + hdf5 + ")"));
  }
}

/// Runs `write`, which writes `temporary`, then puts `temporary` in place of
/// `path`; when `write` throws, runs `on_failure`, removes `temporary` and
/// rethrows (the file at `path` stays as it was).
template <typename Write, typename OnFailure>
void replace_file(const fs::path& path, const fs::path& temporary, Write&& write, OnFailure&& on_failure) {
  try {
    write();
  } catch (...) {
    on_failure();
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw;
  }
  std::error_code error;
  fs::rename(temporary, path, error);
  if (error) fail(path, "cannot replace it with " + temporary.string() + ": " + error.message());
}

/// One extendible dataset of `width` columns (width 0: one-dimensional).
struct Table {
  H5::DataSet dataset;
  H5::DataType type;
  hsize_t width = 0;
  hsize_t rows = 0;
  /// Rows the writer buffered and has not written yet (row-major bytes).
  std::vector<char> pending;

  int rank() const { return width == 0 ? 1 : 2; }
  hsize_t columns() const { return std::max<hsize_t>(width, 1); }
  std::size_t row_bytes() const { return columns() * type.getSize(); }

  /// Appends `n` rows from `data` (row-major).
  void append(const void* data, hsize_t n) {
    if (n == 0) return;
    const hsize_t extent[2] = {rows + n, width};
    dataset.extend(extent);
    const auto [file_space, memory_space] = select_rows(rows, n);
    dataset.write(data, type, memory_space, file_space);
    rows += n;
  }

  /// Reads rows [first, first + n) into `out` (row-major).
  void read(void* out, hsize_t first, hsize_t n) const {
    if (n == 0) return;
    const auto [file_space, memory_space] = select_rows(first, n);
    dataset.read(out, type, memory_space, file_space);
  }

  /// The file space selecting rows [first, first + n), and a memory space of
  /// that shape.
  std::pair<H5::DataSpace, H5::DataSpace> select_rows(hsize_t first, hsize_t n) const {
    H5::DataSpace file_space = dataset.getSpace();
    const hsize_t start[2] = {first, 0};
    const hsize_t count[2] = {n, width};
    file_space.selectHyperslab(H5S_SELECT_SET, count, start);
    return {file_space, H5::DataSpace(rank(), count)};
  }

  template <typename T>
  std::vector<T> read_vector(hsize_t first, hsize_t n) const {
    std::vector<T> out(static_cast<std::size_t>(n * columns()));
    read(out.data(), first, n);
    return out;
  }

  /// Rows [first, first + n) as bytes.
  std::vector<char> read_rows(hsize_t first, hsize_t n) const {
    std::vector<char> out(static_cast<std::size_t>(n) * row_bytes());
    read(out.data(), first, n);
    return out;
  }

  /// Appends the pending rows.
  void write_pending() {
    append(pending.data(), pending.size() / row_bytes());
    pending.clear();
  }
};

/// Offsets read from the file, checked before they size anything: they never
/// decrease and stay within the `rows` of the data they index.
void check_offsets(const std::vector<std::int64_t>& offsets, hsize_t rows, const char* name) {
  if (offsets.empty() || offsets.front() < 0 || !std::is_sorted(offsets.begin(), offsets.end()) ||
      static_cast<hsize_t>(offsets.back()) > rows)
    throw H5::DataSetIException("read", std::string(name) + " decreases or points past its data");
}

/// An attribute of fixed-length strings (text_type): a scalar (one value)
/// or one-dimensional, as wide as its longest value.
void write_text_attribute(H5::H5Object& object, const char* name, const std::vector<std::string>& values, bool scalar) {
  std::size_t width = 1;
  for (const std::string& v : values) width = std::max(width, v.size());
  std::string packed(width * values.size(), '\0');
  for (std::size_t k = 0; k < values.size(); ++k) values[k].copy(packed.data() + k * width, width);
  const hsize_t dims[1] = {values.size()};
  const H5::StrType type = text_type(width);
  object.createAttribute(name, type, scalar ? H5::DataSpace(H5S_SCALAR) : H5::DataSpace(1, dims))
      .write(type, packed.data());
}

/// The values of a string attribute written by write_text_attribute
/// (trailing NULs dropped); refuses a variable-length one, which would be
/// read from the global heap.
std::vector<std::string> read_text_attribute(const H5::Attribute& attribute) {
  if (attribute.getTypeClass() != H5T_STRING)
    throw H5::AttributeIException("read", attribute.getName() + " is not a string");
  const H5::StrType type = attribute.getStrType();
  if (type.isVariableStr()) throw H5::AttributeIException("read", attribute.getName() + " is a variable-length string");
  const std::size_t width = type.getSize();
  const auto n = static_cast<std::size_t>(attribute.getSpace().getSimpleExtentNpoints());
  std::string packed(width * n, '\0');
  if (n > 0) attribute.read(text_type(width), packed.data());
  std::vector<std::string> out;
  for (std::size_t k = 0; k < n; ++k) {
    std::string value = packed.substr(k * width, width);
    value.erase(value.find_last_not_of('\0') + 1);
    out.push_back(std::move(value));
  }
  return out;
}

void write_string_attribute(H5::H5Object& object, const char* name, const std::string& value) {
  write_text_attribute(object, name, {value}, true);
}

/// The value of a scalar string attribute.
std::string read_one_text(const H5::Attribute& attribute) {
  std::vector<std::string> values = read_text_attribute(attribute);
  if (values.size() != 1) throw H5::AttributeIException("read", attribute.getName() + " is not one string");
  return std::move(values.front());
}

/// A scalar string attribute; "" when there is none.
std::string read_string_attribute(const H5::H5Object& object, const char* name) {
  return object.attrExists(name) ? read_one_text(object.openAttribute(name)) : std::string();
}

/// A named option as a typed scalar attribute of `group`: int64, float64 or a UTF-8 string.
void write_option_attribute(H5::Group& group, const NamedOption& option) {
  const H5::DataSpace scalar(H5S_SCALAR);
  if (const auto* integer = std::get_if<std::int64_t>(&option.value))
    group.createAttribute(option.name, H5::PredType::NATIVE_INT64, scalar).write(H5::PredType::NATIVE_INT64, integer);
  else if (const auto* number = std::get_if<double>(&option.value))
    group.createAttribute(option.name, H5::PredType::NATIVE_DOUBLE, scalar).write(H5::PredType::NATIVE_DOUBLE, number);
  else
    write_string_attribute(group, option.name.c_str(), std::get<std::string>(option.value));
}

/// Every attribute of the group `name` as a named option (none when the
/// group is absent), in the order they were written when the group tracks
/// it, else by name.
std::vector<NamedOption> read_option_attributes(const H5::H5File& file, const char* name) {
  std::vector<NamedOption> out;
  if (!file.nameExists(name)) return out;
  const H5::Group group = file.openGroup(name);
  unsigned tracked = 0;
  const hid_t plist = H5Gget_create_plist(group.getId());
  H5Pget_attr_creation_order(plist, &tracked);
  H5Pclose(plist);
  const H5_index_t order = (tracked & H5P_CRT_ORDER_INDEXED) != 0 ? H5_INDEX_CRT_ORDER : H5_INDEX_NAME;
  for (int i = 0; i < group.getNumAttrs(); ++i) {
    const hid_t id =
        H5Aopen_by_idx(group.getId(), ".", order, H5_ITER_INC, static_cast<hsize_t>(i), H5P_DEFAULT, H5P_DEFAULT);
    if (id < 0) throw H5::AttributeIException("read_option_attributes", "cannot open attribute " + std::to_string(i));
    const H5::Attribute attribute(id);
    H5Aclose(id);  // the Attribute holds its own reference
    NamedOption option{attribute.getName(), {}};
    switch (attribute.getTypeClass()) {
      case H5T_INTEGER: {
        std::int64_t value = 0;
        attribute.read(H5::PredType::NATIVE_INT64, &value);
        option.value = value;
        break;
      }
      case H5T_FLOAT: {
        double value = 0;
        attribute.read(H5::PredType::NATIVE_DOUBLE, &value);
        option.value = value;
        break;
      }
      case H5T_STRING: option.value = read_one_text(attribute); break;
      default:
        throw H5::AttributeIException("read_option_attributes", std::string(name) + "/" + option.name +
                                                                    " is not an integer, a number or a string");
    }
    out.push_back(std::move(option));
  }
  return out;
}

/// The group `classes`, as attributes: `name`, `parent` (C,) and
/// `model_offset` (C + 1,): class c lists the models
/// `model[model_offset[c]:model_offset[c + 1]]` of `model` (M,), in .cla
/// order; `file` names the .cla file.
void write_classes(H5::H5File& file, const std::vector<PsbClass>& classes, const std::string& source) {
  H5::Group group = file.createGroup("classes");
  std::vector<std::string> names, parents, models;
  std::vector<std::int64_t> offset = {0};
  for (const PsbClass& c : classes) {
    names.push_back(c.name);
    parents.push_back(c.parent);
    models.insert(models.end(), c.models.begin(), c.models.end());
    offset.push_back(static_cast<std::int64_t>(models.size()));
  }
  write_text_attribute(group, "name", names, false);
  write_text_attribute(group, "parent", parents, false);
  write_text_attribute(group, "model", models, false);
  const hsize_t dims[1] = {offset.size()};
  group.createAttribute("model_offset", H5::PredType::NATIVE_INT64, H5::DataSpace(1, dims))
      .write(H5::PredType::NATIVE_INT64, offset.data());
  write_string_attribute(group, "file", source);
}

void read_classes(const H5::H5File& file, Provenance& provenance) {
  if (!file.nameExists("classes")) return;
  const H5::Group group = file.openGroup("classes");
  const std::vector<std::string> names = read_text_attribute(group.openAttribute("name")),
                                 parents = read_text_attribute(group.openAttribute("parent")),
                                 models = read_text_attribute(group.openAttribute("model"));
  const H5::Attribute offsets = group.openAttribute("model_offset");
  std::vector<std::int64_t> offset(static_cast<std::size_t>(offsets.getSpace().getSimpleExtentNpoints()));
  offsets.read(H5::PredType::NATIVE_INT64, offset.data());
  if (offset.size() != names.size() + 1 || parents.size() != names.size() || offset.front() != 0 ||
      offset.back() != static_cast<std::int64_t>(models.size()) || !std::is_sorted(offset.begin(), offset.end()))
    throw H5::GroupIException("read_classes", "the classes group is inconsistent");
  for (std::size_t c = 0; c < names.size(); ++c)
    provenance.classes.push_back(
        {names[c], parents[c], std::vector<std::string>(models.begin() + offset[c], models.begin() + offset[c + 1])});
  provenance.classes_file = read_string_attribute(group, "file");
}

std::string utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

/// What the rows of a dataset are: each entry adds one row to kEntry and
/// rows of its own to each other part (the bytes of its name, its nodes,
/// ...), which an offsets dataset indexes.
enum Part : int { kEntry, kNameByte, kClassByte, kErrorByte, kNode, kEdge, kFeaturePoint, kSkeletonPoint, kPartCount };

/// A dataset of the layout: its name, element type and columns, what its
/// rows are and how an entry's rows are made and read back. Either the
/// values of a part (`put`, `take`) or the offsets into one (`indexes`).
struct Dataset {
  const char* name = "";
  const H5::PredType* type = nullptr;  ///< in the file and in memory
  std::vector<std::string> columns;    ///< of a 2-D dataset (its `columns` attribute); none: 1-D
  Part part = kEntry;                  ///< what one of its rows is
  /// Offsets: one row more than `part` has (a leading 0), row r + 1 the
  /// number of rows of `indexes` up to the end of row r of `part`. kEntry:
  /// a values dataset.
  Part indexes = kEntry;
  /// Offsets of a part other than kEntry: the entry's own offsets into
  /// `indexes`, #rows of `part` + 1 from 0 (empty: no rows of `indexes`).
  std::vector<std::int64_t> GraphRecord::*local = nullptr;
  /// Values: appends the entry's rows (row-major bytes) to `rows`, and sets
  /// them back from its `count` values at `data`.
  std::function<void(const GraphRecord& entry, std::vector<char>& rows)> put;
  std::function<void(GraphRecord& entry, const char* data, std::size_t count)> take;

  bool is_offsets() const { return indexes != kEntry; }
};

/// The HDF5 type of the numbers T (char: the UTF-8 bytes of a string).
template <typename T>
const H5::PredType& type_of() {
  if constexpr (std::is_same_v<T, char>)
    return H5::PredType::NATIVE_UINT8;
  else if constexpr (std::is_same_v<T, std::int8_t>)
    return H5::PredType::NATIVE_INT8;
  else if constexpr (std::is_same_v<T, std::int32_t>)
    return H5::PredType::NATIVE_INT32;
  else if constexpr (std::is_same_v<T, std::int64_t>)
    return H5::PredType::NATIVE_INT64;
  else if constexpr (std::is_same_v<T, std::uint64_t>)
    return H5::PredType::NATIVE_UINT64;
  else {
    static_assert(std::is_same_v<T, double>, "a number type of the layout");
    return H5::PredType::NATIVE_DOUBLE;
  }
}

/// The numbers a record member holds: itself, or the elements of a vector,
/// an array or a string.
template <typename M>
struct Element {
  using type = M;
};
template <typename T>
struct Element<std::vector<T>> {
  using type = T;
};
template <typename T, std::size_t N>
struct Element<std::array<T, N>> {
  using type = T;
};
template <>
struct Element<std::string> {
  using type = char;
};

template <typename M>
void resize_to(M& values, std::size_t count) {
  values.resize(count);
}
template <typename T, std::size_t N>
void resize_to(std::array<T, N>&, std::size_t) {}  // as wide as its dataset

void append_bytes(std::vector<char>& rows, const void* data, std::size_t bytes) {
  const char* first = static_cast<const char*>(data);
  rows.insert(rows.end(), first, first + bytes);
}

Dataset make_dataset(const char* name, const H5::PredType& type, Part part) {
  Dataset d;
  d.name = name;
  d.type = &type;
  d.part = part;
  return d;
}

/// The values of the record's `member` (a number, or a vector, array or
/// string of them), one row of `columns` values per row of `part`.
template <typename M, std::size_t N = 0>
Dataset values(const char* name, Part part, M GraphRecord::*member, const std::array<const char*, N>& columns = {}) {
  using T = typename Element<M>::type;
  Dataset d = make_dataset(name, type_of<T>(), part);
  d.columns.assign(columns.begin(), columns.end());
  d.put = [member](const GraphRecord& entry, std::vector<char>& rows) {
    const M& m = entry.*member;
    if constexpr (std::is_arithmetic_v<M>)
      append_bytes(rows, &m, sizeof m);
    else
      append_bytes(rows, m.data(), m.size() * sizeof(T));
  };
  d.take = [member](GraphRecord& entry, const char* data, std::size_t count) {
    M& m = entry.*member;
    if constexpr (std::is_arithmetic_v<M>) {
      std::copy_n(data, sizeof m, reinterpret_cast<char*>(&m));
    } else {
      resize_to(m, count);
      std::copy_n(data, count * sizeof(T), reinterpret_cast<char*>(m.data()));
    }
  };
  return d;
}

/// `status`: 0 for an entry with a graph, 1 for a failed one.
Dataset status_values() {
  Dataset d = make_dataset("status", type_of<std::int8_t>(), kEntry);
  d.put = [](const GraphRecord& entry, std::vector<char>& rows) { rows.push_back(entry.ok ? 0 : 1); };
  d.take = [](GraphRecord& entry, const char* data, std::size_t) { entry.ok = data[0] == 0; };
  return d;
}

/// The offsets of the rows of `indexes`, per row of `part`.
Dataset offsets(const char* name, Part part, Part indexes, std::vector<std::int64_t> GraphRecord::*local = nullptr) {
  Dataset d = make_dataset(name, type_of<std::int64_t>(), part);
  d.indexes = indexes;
  d.local = local;
  return d;
}

/// Every dataset of the layout (docs/collection-file.md), in the order the
/// file creates them; the offsets of a part come before any offsets into
/// it. The writer, the reader and resume follow this table: a dataset is
/// one row.
const std::vector<Dataset>& datasets() {
  static const std::vector<Dataset> table = {
      values("name", kNameByte, &GraphRecord::name),
      offsets("name_offset", kEntry, kNameByte),
      values("class", kClassByte, &GraphRecord::class_label),
      offsets("class_offset", kEntry, kClassByte),
      values("error", kErrorByte, &GraphRecord::error),
      offsets("error_offset", kEntry, kErrorByte),
      values("content_hash", kEntry, &GraphRecord::content_hash),
      values("vertices", kEntry, &GraphRecord::vertices),
      values("faces", kEntry, &GraphRecord::faces),
      status_values(),
      values("timings", kEntry, &GraphRecord::timings, kTimeColumnNames),
      values("signature", kEntry, &GraphRecord::signature, kSignatureNames),
      offsets("node_offset", kEntry, kNode),
      offsets("edge_offset", kEntry, kEdge),
      offsets("feature_offset", kEntry, kFeaturePoint),
      values("nodes", kNode, &GraphRecord::nodes, kNodeColumnNames),
      values("node_geometry", kNode, &GraphRecord::node_geometry, kGeomColumnNames),
      values("node_attr", kNode, &GraphRecord::node_attributes, kNodeAttributeNames),
      offsets("skeleton_offset", kNode, kSkeletonPoint, &GraphRecord::skeleton_offset),
      values("skeleton_points", kSkeletonPoint, &GraphRecord::skeleton_points, kPointColumnNames),
      values("edges", kEdge, &GraphRecord::edges, kEdgeColumnNames),
      values("edge_attr", kEdge, &GraphRecord::edge_attributes, kEdgeAttributeNames),
      values("feature_points", kFeaturePoint, &GraphRecord::feature_points),
  };
  return table;
}

/// The row of datasets() called `name`.
std::size_t dataset_index(const char* name) {
  for (std::size_t d = 0; d < datasets().size(); ++d)
    if (std::strcmp(datasets()[d].name, name) == 0) return d;
  throw std::logic_error(std::string("no dataset ") + name);
}

/// The datasets of an open file.
struct Tables {
  std::vector<Table> table;  ///< one per row of datasets(), in its order
  /// The number of committed entries: one int64, contiguous, so that a
  /// commit is one 8-byte write in place.
  H5::DataSet count;

  /// The dataset called `name`.
  const Table& named(const char* name) const { return table[dataset_index(name)]; }

  /// The rows of `part` that every dataset of its values has.
  hsize_t rows_of(Part part) const {
    hsize_t rows = std::numeric_limits<hsize_t>::max();
    for (std::size_t d = 0; d < table.size(); ++d)
      if (datasets()[d].part == part && !datasets()[d].is_offsets()) rows = std::min(rows, table[d].rows);
    return rows;
  }
};

/// Opens the dataset `name` of `file` as a table of `spec`'s type and columns.
Table open_table(const H5::H5File& file, const char* name, const Dataset& spec) {
  Table t;
  t.dataset = file.openDataSet(name);
  t.type = *spec.type;
  t.width = spec.columns.size();
  hsize_t dims[2] = {0, 0};
  const H5::DataSpace space = t.dataset.getSpace();
  if (space.getSimpleExtentNdims() != t.rank())
    throw H5::DataSetIException("open", std::string(name) + ": unexpected rank");
  space.getSimpleExtentDims(dims);
  if (t.width != 0 && dims[1] != t.width)
    throw H5::DataSetIException("open", std::string(name) + ": unexpected column count");
  t.rows = dims[0];
  return t;
}

/// Opens every dataset of `file` (reading, or appending after the rows it has).
Tables open_tables(const H5::H5File& file) {
  Tables tables;
  for (const Dataset& spec : datasets()) tables.table.push_back(open_table(file, spec.name, spec));
  tables.count = file.openDataSet("count");
  return tables;
}

void check_entry(const GraphRecord& e, const fs::path& path) {
  const std::size_t n = static_cast<std::size_t>(e.num_nodes());
  const std::size_t m = static_cast<std::size_t>(e.num_edges());
  const auto expect = [&](bool ok, const char* what) {
    if (!ok) throw InvalidArgument(path.string() + ": entry '" + e.name + "': " + what);
  };
  expect(e.nodes.size() % kNodeColumnCount == 0 && e.edges.size() % 2 == 0, "nodes or edges not whole rows");
  expect(e.node_geometry.size() == n * kGeomColumnCount, "node_geometry is not #nodes x kGeomColumnCount");
  expect(e.node_attributes.size() == n * kNodeAttributeCount, "node_attributes is not #nodes x kNodeAttributeCount");
  expect(e.edge_attributes.size() == m * kEdgeAttributeCount, "edge_attributes is not #edges x kEdgeAttributeCount");
  expect(e.skeleton_offset.empty() || e.skeleton_offset.size() == n + 1, "skeleton_offset is not #nodes + 1");
  expect(e.skeleton_offset.empty() || e.skeleton_offset.front() == 0, "skeleton_offset does not start at 0");
  expect(std::is_sorted(e.skeleton_offset.begin(), e.skeleton_offset.end()), "skeleton_offset decreases");
  const std::size_t points = e.skeleton_offset.empty() ? 0 : static_cast<std::size_t>(e.skeleton_offset.back());
  expect(e.skeleton_points.size() == 3 * points, "skeleton_points is not 3 x skeleton_offset.back()");
  expect(e.signature.empty() || e.signature.size() == kSignatureLength, "signature is not kSignatureLength long");
  for (const std::int32_t id : e.edges)
    expect(id >= 0 && static_cast<std::size_t>(id) < n, "edge names a node out of range");
}

int vfd_descriptor(const H5::H5File& file) {
  void* handle = nullptr;
  if (H5Fget_vfd_handle(file.getId(), H5P_DEFAULT, &handle) < 0 || handle == nullptr)
    throw H5::FileIException("H5Fget_vfd_handle", "no file descriptor");
  return *static_cast<int*>(handle);
}

/// Flushes HDF5's caches to the file and the file to the disk.
void flush_to_disk(const H5::H5File& file, const fs::path& path) {
  file.flush(H5F_SCOPE_LOCAL);
  if (::fsync(vfd_descriptor(file)) != 0) fail(path, std::string("fsync failed: ") + std::strerror(errno));
}

/// The committed part of a collection file: its entry count (checked
/// against the rows written) and provenance. The per-entry columns are read
/// when asked (CollectionReader), so that opening a collection of a million
/// entries to query it reads little.
struct Snapshot {
  std::int64_t size = 0;
  Provenance provenance;
};

/// Metadata read attempts of a reader in SWMR mode (HDF5's default: 100).
constexpr unsigned kSwmrReadAttempts = 4;

H5::H5File open_for_reading(const fs::path& path) {
  if (!fs::exists(path)) fail(path, "no such file");
  complete_interrupted_write(path);  // a writer killed inside a write (store/write_journal.h)
  if (H5Fis_hdf5(path.c_str()) <= 0) fail(path, "not an HDF5 file");
  try {
    return H5::H5File(path.string(), H5F_ACC_RDONLY);
  } catch (const H5::Exception&) {
    // A writer died with the file open: the superblock still says so, and
    // HDF5 opens such a file only in SWMR read mode (see the top of the file).
  }
  // In SWMR read mode HDF5 retries a metadata read whose checksum fails,
  // waiting longer each time (up to an hour in all): meant for a reader racing
  // a live writer, it turns a corrupted file into a hang. A few quick
  // attempts cover the race.
  H5::FileAccPropList access;
  H5Pset_metadata_read_attempts(access.getId(), kSwmrReadAttempts);
  return guarded(path, "opening", [&] {
    return H5::H5File(path.string(), H5F_ACC_RDONLY | H5F_ACC_SWMR_READ, H5::FileCreatPropList::DEFAULT, access);
  });
}

int layout_version(const H5::H5File& file) {
  if (!file.attrExists("layout")) return -1;
  int version = -1;
  file.openAttribute("layout").read(H5::PredType::NATIVE_INT, &version);
  return version;
}

/// The entries' offsets into `part`, rows [first, first + n) of their
/// dataset, checked.
std::vector<std::int64_t> read_entry_offsets(const Tables& t, Part part, std::int64_t first, std::int64_t n) {
  for (std::size_t d = 0; d < t.table.size(); ++d) {
    const Dataset& spec = datasets()[d];
    if (spec.part != kEntry || spec.indexes != part) continue;
    std::vector<std::int64_t> offsets =
        t.table[d].read_vector<std::int64_t>(static_cast<hsize_t>(first), static_cast<hsize_t>(n));
    check_offsets(offsets, t.rows_of(part), spec.name);
    return offsets;
  }
  throw H5::DataSetIException("read", "no offsets into a part");  // not reached: every part has its offsets
}

/// The offsets (size + 1 of them, checked) of the entries of `s` into
/// `part`, read whole.
std::vector<std::int64_t> entry_offsets(const Tables& t, const Snapshot& s, Part part) {
  return read_entry_offsets(t, part, 0, s.size + 1);
}

/// Entry i's text in the text dataset `name` (`name`, `class`), read alone:
/// its two offsets, then its bytes.
std::string read_text(const Tables& t, const char* name, std::int64_t i) {
  const std::size_t d = dataset_index(name);
  const std::vector<std::int64_t> ends = read_entry_offsets(t, datasets()[d].part, i, 2);
  const auto text =
      t.table[d].read_vector<char>(static_cast<hsize_t>(ends[0]), static_cast<hsize_t>(ends[1] - ends[0]));
  return {text.begin(), text.end()};
}

/// A text dataset of the entries (`name`, `class`): its bytes and each
/// entry's end in them, read whole.
struct TextColumn {
  std::vector<std::int64_t> ends;  ///< size + 1, checked
  std::vector<char> text;

  TextColumn(const Tables& t, const Snapshot& s, const char* name) {
    const std::size_t d = dataset_index(name);
    ends = entry_offsets(t, s, datasets()[d].part);
    text = t.table[d].read_vector<char>(0, static_cast<hsize_t>(ends.back()));
  }
  std::string_view at(std::size_t k) const {
    return {text.data() + ends[k], static_cast<std::size_t>(ends[k + 1] - ends[k])};
  }
  std::vector<std::string> strings() const {
    std::vector<std::string> out;
    out.reserve(ends.size() - 1);
    for (std::size_t k = 0; k + 1 < ends.size(); ++k) out.emplace_back(at(k));
    return out;
  }
};

Snapshot read_snapshot(const H5::H5File& file, const Tables& t) {
  Snapshot s;
  t.count.read(&s.size, H5::PredType::NATIVE_INT64);
  const auto g = static_cast<hsize_t>(s.size);  // checked below before it sizes anything
  for (std::size_t d = 0; d < t.table.size(); ++d) {
    const Dataset& spec = datasets()[d];
    if (spec.part == kEntry && (s.size < 0 || t.table[d].rows < g + (spec.is_offsets() ? 1 : 0)))
      throw H5::DataSetIException("read", "count (" + std::to_string(s.size) + ") exceeds the rows written");
  }
  s.provenance.reebkit_version = read_string_attribute(file, "reebkit_version");
  s.provenance.options = read_string_attribute(file, "options");
  s.provenance.command = read_string_attribute(file, "command");
  s.provenance.created = read_string_attribute(file, "created");
  s.provenance.analysis_options = read_option_attributes(file, "analysis_options");
  read_classes(file, s.provenance);
  return s;
}

/// An open collection file, checked, and its committed part.
struct OpenCollection {
  H5::H5File file;
  Tables tables;
  Snapshot snapshot;
};

OpenCollection open_collection(const fs::path& path) {
  OpenCollection c;
  c.file = open_for_reading(path);
  const int version = guarded(path, "reading the layout", [&] { return layout_version(c.file); });
  if (version != kCollectionLayoutVersion)
    fail(path, version < 0 ? "not a reebkit collection file (no `layout` attribute)"
                           : "collection layout version " + std::to_string(version) + ", this reebkit reads " +
                                 std::to_string(kCollectionLayoutVersion) + ": re-index the meshes with this version");
  guarded(path, "reading", [&] {
    c.tables = open_tables(c.file);
    c.snapshot = read_snapshot(c.file, c.tables);
  });
  return c;
}

/// Every entry's offsets into each part (size + 1, checked), indexed by part.
using EntryOffsets = std::array<std::vector<std::int64_t>, kPartCount>;

/// Whether EntryParts::Outline reads dataset `spec`: not the per-node and
/// per-edge attributes, node geometry, skeletons, timings and signature.
bool in_outline(const Dataset& spec) {
  for (const char* left_out :
       {"timings", "signature", "node_geometry", "node_attr", "skeleton_offset", "skeleton_points", "edge_attr"})
    if (std::strcmp(spec.name, left_out) == 0) return false;
  return true;
}

/// Entries [first, first + n) read with one call per dataset (those of
/// `parts`); their offsets from `offsets` when given (read whole before),
/// else read with them.
std::vector<GraphRecord> read_entries(const Tables& t, const EntryOffsets* offsets, std::int64_t first, std::int64_t n,
                                      EntryParts parts = EntryParts::Whole) {
  const std::vector<Dataset>& specs = datasets();
  const auto read = [parts](const Dataset& spec) { return parts == EntryParts::Whole || in_outline(spec); };
  std::vector<GraphRecord> out(static_cast<std::size_t>(n));
  // Entry k's rows of part p: [bounds[p][k], bounds[p][k + 1]).
  std::array<std::vector<std::int64_t>, kPartCount> bounds;
  for (std::int64_t k = 0; k <= n; ++k) bounds[kEntry].push_back(first + k);
  for (std::size_t d = 0; d < specs.size(); ++d) {
    const Dataset& spec = specs[d];
    if (!spec.is_offsets() || !read(spec)) continue;
    const std::vector<std::int64_t>& rows = bounds[spec.part];
    const std::int64_t row0 = rows.front();
    std::vector<std::int64_t> offset;
    if (spec.part == kEntry && offsets != nullptr) {
      const std::vector<std::int64_t>& whole = (*offsets)[spec.indexes];
      offset.assign(whole.begin() + first, whole.begin() + first + n + 1);
    } else {
      offset = t.table[d].read_vector<std::int64_t>(static_cast<hsize_t>(row0),
                                                    static_cast<hsize_t>(rows.back() - row0 + 1));
      check_offsets(offset, t.rows_of(spec.indexes), spec.name);
    }
    for (const std::int64_t r : rows) bounds[spec.indexes].push_back(offset[static_cast<std::size_t>(r - row0)]);
    if (spec.local == nullptr) continue;
    for (std::size_t k = 0; k < out.size(); ++k) {
      std::vector<std::int64_t>& local = out[k].*spec.local;
      local.assign(offset.begin() + (rows[k] - row0), offset.begin() + (rows[k + 1] - row0) + 1);
      const std::int64_t local0 = local.front();
      for (std::int64_t& o : local) o -= local0;
    }
  }
  for (std::size_t d = 0; d < specs.size(); ++d) {
    const Dataset& spec = specs[d];
    if (spec.is_offsets() || !read(spec)) continue;
    const Table& table = t.table[d];
    const std::vector<std::int64_t>& rows = bounds[spec.part];
    const std::int64_t row0 = rows.front();
    const std::vector<char> data =
        table.read_rows(static_cast<hsize_t>(row0), static_cast<hsize_t>(rows.back() - row0));
    for (std::size_t k = 0; k < out.size(); ++k)
      spec.take(out[k], data.data() + static_cast<std::size_t>(rows[k] - row0) * table.row_bytes(),
                static_cast<std::size_t>(rows[k + 1] - rows[k]) * table.columns());
  }
  return out;
}

}  // namespace

void print_hdf5_error_stacks(bool on) { print_error_stacks = on; }

// ---------------------------------------------------------------------------
// Reader

struct CollectionReader::Impl : OpenCollection {
  fs::path path;
  // The per-entry columns, each read on first use: a query with the query
  // file reads the names (to find the query by its name) and a few
  // classes, not the rest.
  mutable std::optional<TextColumn> name_text, class_text;
  mutable std::optional<std::vector<std::string>> names, class_labels;
  mutable std::optional<std::vector<std::uint64_t>> hashes;
  /// The entries by name, built on the second find(): the first scans the
  /// names (a query by name need not hash every name of a large collection).
  mutable std::unordered_map<std::string, std::int64_t> by_name;
  mutable bool found_once = false;
  /// The signature matrix, read on the first signatures() (a query with a
  /// query file never reads it).
  mutable std::optional<std::vector<double>> signatures;

  /// `column`, read on first use, as `doing` says.
  template <typename T, typename Read>
  const T& lazy(std::optional<T>& column, const char* doing, Read&& read) const {
    if (!column) column = guarded(path, doing, read);
    return *column;
  }
  const TextColumn& text(std::optional<TextColumn>& column, const char* name) const {
    return lazy(column, "reading the entries' text", [&] { return TextColumn(tables, snapshot, name); });
  }
  /// Entries read so far with their own offsets; past kEntriesReadAlone the
  /// offsets are read whole (entries looked up one by one: Python's c[i]).
  mutable std::int64_t entries_read_alone = 0;
  static constexpr std::int64_t kEntriesReadAlone = 64;
  mutable std::optional<EntryOffsets> offsets;
  /// The whole offsets when they were read, or are now worth reading
  /// before `count` more entries; nullptr: read them with the entries.
  const EntryOffsets* offsets_for(std::int64_t count) const {
    if (!offsets && (entries_read_alone += count) > kEntriesReadAlone) all_offsets();
    return offsets ? &*offsets : nullptr;
  }
  /// Every entry's offsets, read whole on first use.
  const EntryOffsets& all_offsets() const {
    return lazy(offsets, "reading the offsets", [&] {
      EntryOffsets whole;
      for (const Dataset& spec : datasets())
        if (spec.part == kEntry && spec.is_offsets())
          whole[spec.indexes] = entry_offsets(tables, snapshot, spec.indexes);
      return whole;
    });
  }
  /// Throws InvalidArgument unless entry i is in the file.
  void check_entry(std::int64_t i) const {
    if (i < 0 || i >= snapshot.size)
      throw InvalidArgument(path.string() + ": entry " + std::to_string(i) + " out of range (the file holds " +
                            std::to_string(snapshot.size) + ")");
  }
  /// Texts read alone so far; past kTextsReadAlone a column is read whole
  /// (a process that keeps querying: its later results are then look-ups).
  mutable int texts_read_alone = 0;
  static constexpr int kTextsReadAlone = 200;
  /// Entry i's text, from `column` when it was read, else read alone.
  std::string text_of(std::optional<TextColumn>& column, const char* name, std::int64_t i) const {
    check_entry(i);
    if (column || ++texts_read_alone > kTextsReadAlone)
      return std::string(text(column, name).at(static_cast<std::size_t>(i)));
    return guarded(path, "reading the entries' text", [&] { return read_text(tables, name, i); });
  }
};

CollectionReader::CollectionReader(const fs::path& path) : impl_(std::make_unique<Impl>()) {
  H5::Exception::dontPrint();
  impl_->path = path;
  static_cast<OpenCollection&>(*impl_) = open_collection(path);
}

CollectionReader::~CollectionReader() = default;
CollectionReader::CollectionReader(CollectionReader&&) noexcept = default;

std::int64_t CollectionReader::size() const { return impl_->snapshot.size; }
const std::vector<std::string>& CollectionReader::names() const {
  return impl_->lazy(impl_->names, "reading the names",
                     [&] { return impl_->text(impl_->name_text, "name").strings(); });
}
const std::vector<std::string>& CollectionReader::class_labels() const {
  return impl_->lazy(impl_->class_labels, "reading the classes",
                     [&] { return impl_->text(impl_->class_text, "class").strings(); });
}
std::string CollectionReader::name(std::int64_t i) const { return impl_->text_of(impl_->name_text, "name", i); }
std::string CollectionReader::class_label(std::int64_t i) const {
  return impl_->text_of(impl_->class_text, "class", i);
}
const std::vector<std::uint64_t>& CollectionReader::content_hashes() const {
  return impl_->lazy(impl_->hashes, "reading the content hashes", [&] {
    return impl_->tables.named("content_hash").read_vector<std::uint64_t>(0, static_cast<hsize_t>(size()));
  });
}
const std::vector<double>& CollectionReader::signatures() const {
  return impl_->lazy(impl_->signatures, "reading the signatures", [&] {
    return impl_->tables.named("signature").read_vector<double>(0, static_cast<hsize_t>(size()));
  });
}
const Provenance& CollectionReader::provenance() const { return impl_->snapshot.provenance; }

std::optional<std::int64_t> CollectionReader::find(const std::string& name) const {
  const TextColumn& names = impl_->text(impl_->name_text, "name");
  const auto count = static_cast<std::size_t>(size());
  if (!impl_->found_once) {
    impl_->found_once = true;
    for (std::size_t i = 0; i < count; ++i)
      if (names.at(i) == name) return static_cast<std::int64_t>(i);
    return std::nullopt;
  }
  if (impl_->by_name.empty())
    for (std::size_t i = 0; i < count; ++i) impl_->by_name.emplace(names.at(i), static_cast<std::int64_t>(i));
  const auto it = impl_->by_name.find(name);
  if (it == impl_->by_name.end()) return std::nullopt;
  return it->second;
}

GraphRecord CollectionReader::entry(std::int64_t i) const {
  impl_->check_entry(i);
  return guarded(impl_->path, "reading an entry",
                 [&] { return std::move(read_entries(impl_->tables, impl_->offsets_for(1), i, 1).front()); });
}

std::vector<GraphRecord> CollectionReader::entries(std::int64_t first, std::int64_t count, EntryParts parts) const {
  if (first < 0 || count < 0 || first + count > size())
    throw InvalidArgument(impl_->path.string() + ": entries " + std::to_string(first) + " to " +
                          std::to_string(first + count - 1) + " out of range (the file holds " +
                          std::to_string(size()) + ")");
  if (count == 0) return {};
  return guarded(impl_->path, "reading entries",
                 [&] { return read_entries(impl_->tables, impl_->offsets_for(count), first, count, parts); });
}

void CollectionReader::for_each_entry(const std::function<void(std::int64_t, const GraphRecord&)>& visit,
                                      EntryParts parts, std::int64_t batch) const {
  if (batch < 1) throw InvalidArgument(impl_->path.string() + ": for_each_entry needs a batch of 1 entry or more");
  for (std::int64_t first = 0; first < size(); first += batch) {
    const std::vector<GraphRecord> block = entries(first, std::min(batch, size() - first), parts);
    for (std::size_t k = 0; k < block.size(); ++k) visit(first + static_cast<std::int64_t>(k), block[k]);
  }
}

// ---------------------------------------------------------------------------
// Writer

struct CollectionWriter::Impl {
  fs::path path;
  H5::H5File file;
  Tables tables;
  std::vector<std::pair<std::string, std::uint64_t>> existing;
  std::int64_t written = 0;    // entries in the datasets
  std::int64_t committed = 0;  // entries counted by `count`
  std::int64_t buffered = 0;   // entries in the tables' pending rows
  // the rows of each part, pending rows included
  std::array<std::int64_t, kPartCount> totals{};

  void create(const fs::path& target, const Provenance& provenance);
  void write_batch();
  void commit();
  /// Runs the write step `body` (guarded); on failure abandons the file and rethrows.
  template <typename Body>
  void write_step(const fs::path& target, const char* doing, Body&& body) {
    try {
      guarded(target, doing, body);
    } catch (...) {
      abandon();
      throw;
    }
  }
  /// Lets go of a file that failed to be written, leaving it as its last
  /// checkpoint left it. HDF5 would retry the failed writes when closing
  /// it, fail again (and HDF5 1.10 crashes at exit on a file it could not
  /// close), so the file's descriptor is first pointed at /dev/null: the
  /// writes still pending go nowhere and every handle closes.
  void abandon() noexcept;
};

void CollectionWriter::Impl::abandon() noexcept {
  if (file.getId() == H5I_INVALID_HID) return;
  void* handle = nullptr;
  if (H5Fget_vfd_handle(file.getId(), H5P_DEFAULT, &handle) >= 0 && handle != nullptr) {
    stop_write_journal(*static_cast<int*>(handle));
    const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (null >= 0) {
      ::dup2(null, *static_cast<int*>(handle));
      ::close(null);
    }
  }
  try {
    tables = Tables{};
    file.close();
  } catch (const H5::Exception&) {
    // Nothing more can be done: the file on disk is as the last checkpoint
    // left it. HDF5 keeps the id of a file it failed to close and crashes
    // when asked to close it again, as H5File's destructor would (a write
    // that failed while the file was being created): let go of the id.
    new (&file) H5::H5File();
  }
  buffered = 0;
}

namespace {

// Rows are only appended, so each dataset needs just its last chunk cached:
// a 64 KiB chunk cache per dataset (default 1 MiB) and a metadata cache of at
// most 2 MiB (default: grows to 32 MiB with the chunk index) keep the
// writer's memory flat however long the collection.
void limit_caches(H5::FileAccPropList& access_list) {
  access_list.setCache(0, 521, 64 * 1024, 1.0);
  H5AC_cache_config_t config;
  config.version = H5AC__CURR_CACHE_CONFIG_VERSION;
  H5Pget_mdc_config(access_list.getId(), &config);
  config.set_initial_size = true;
  config.initial_size = 1 << 20;
  config.min_size = 1 << 20;
  config.max_size = 2 << 20;
  H5Pset_mdc_config(access_list.getId(), &config);
}

}  // namespace

void CollectionWriter::Impl::create(const fs::path& target, const Provenance& provenance) {
  H5::FileCreatPropList create_list;
  // Never reuse freed space: see the top of the file.
  H5Pset_file_space_strategy(create_list.getId(), H5F_FSPACE_STRATEGY_NONE, false, 1);
  H5::FileAccPropList access_list;
  access_list.setLibverBounds(H5F_LIBVER_LATEST, H5F_LIBVER_LATEST);  // SWMR needs the 1.10 format
  limit_caches(access_list);
  use_write_journal(access_list.getId());  // see the top of the file
  file = H5::H5File(target.string(), H5F_ACC_TRUNC, create_list, access_list);

  const int layout = kCollectionLayoutVersion;
  file.createAttribute("layout", H5::PredType::NATIVE_INT, H5::DataSpace(H5S_SCALAR))
      .write(H5::PredType::NATIVE_INT, &layout);
  write_string_attribute(file, "reebkit_version", provenance.reebkit_version);
  write_string_attribute(file, "options", provenance.options);
  write_string_attribute(file, "command", provenance.command);
  write_string_attribute(file, "created", provenance.created.empty() ? utc_now() : provenance.created);
  // The options read back in the order they were written (creation order
  // tracked: past eight attributes HDF5 would list them by name hash).
  const hid_t ordered = H5Pcreate(H5P_GROUP_CREATE);
  H5Pset_attr_creation_order(ordered, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED);
  const hid_t group_id = H5Gcreate2(file.getId(), "analysis_options", H5P_DEFAULT, ordered, H5P_DEFAULT);
  H5Pclose(ordered);
  if (group_id < 0) throw H5::GroupIException("CollectionWriter", "cannot create the group analysis_options");
  H5::Group analysis(group_id);  // holds its own reference
  H5Gclose(group_id);
  for (const NamedOption& option : provenance.analysis_options) write_option_attribute(analysis, option);
  if (!provenance.classes.empty()) write_classes(file, provenance.classes, provenance.classes_file);

  for (const Dataset& spec : datasets()) {
    Table& t = tables.table.emplace_back();
    t.type = *spec.type;
    t.width = spec.columns.size();
    const hsize_t dims[2] = {0, t.width};
    const hsize_t max_dims[2] = {H5S_UNLIMITED, t.width};
    const hsize_t chunk[2] = {std::max<hsize_t>(1, kChunkBytes / t.row_bytes()), t.width};
    H5::DSetCreatPropList properties;
    properties.setChunk(t.rank(), chunk);
    properties.setShuffle();
    properties.setDeflate(kDeflateLevel);
    t.dataset = file.createDataSet(spec.name, t.type, H5::DataSpace(t.rank(), dims, max_dims), properties);
  }
  for (std::size_t d = 0; d < datasets().size(); ++d) {
    const Dataset& spec = datasets()[d];
    if (!spec.columns.empty()) write_text_attribute(tables.table[d].dataset, "columns", spec.columns, false);
  }
  const std::int64_t zero = 0;
  for (std::size_t d = 0; d < datasets().size(); ++d)
    if (datasets()[d].is_offsets()) tables.table[d].append(&zero, 1);
  const hsize_t one[1] = {1};
  tables.count = file.createDataSet("count", H5::PredType::NATIVE_INT64, H5::DataSpace(1, one));
  tables.count.write(&zero, H5::PredType::NATIVE_INT64);
  // Entering SWMR mode takes HDF5's file lock anew; a reader that opened the
  // new file a moment before (`reeb info` on a run in progress, a process
  // polling for it) holds it for as long as it reads the header, so the
  // switch is tried again for up to a second before it counts as a failure.
  for (int attempt = 0; H5Fstart_swmr_write(file.getId()) < 0; ++attempt) {
    if (attempt == 50) throw H5::FileIException("H5Fstart_swmr_write", "failed (another process keeps the file open?)");
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

void CollectionWriter::Impl::write_batch() {
  if (buffered == 0) return;
  for (Table& t : tables.table) t.write_pending();
  written += buffered;
  buffered = 0;
}

void CollectionWriter::Impl::commit() {
  write_batch();
  if (written == committed) return;
  flush_to_disk(file, path);  // phase 1: every row of the new entries
  tables.count.write(&written, H5::PredType::NATIVE_INT64);
  flush_to_disk(file, path);  // phase 2: the count that makes them visible
  committed = written;
}

CollectionWriter::CollectionWriter(const fs::path& path, const Provenance& provenance, bool resume)
    : impl_(std::make_unique<Impl>()) {
  H5::Exception::dontPrint();
  Impl& w = *impl_;
  w.path = path;
  if (!resume || !fs::exists(path)) {
    w.write_step(path, "creating", [&] { w.create(path, provenance); });
    return;
  }
  // Resume: copy the committed entries into a fresh file, then put it in place.
  fs::path temporary = path;
  temporary += ".resume-tmp";
  replace_file(
      path, temporary,
      [&] {
        const OpenCollection old = open_collection(path);
        w.write_step(temporary, "creating", [&] { w.create(temporary, provenance); });
        const std::int64_t n = old.snapshot.size;
        for (std::int64_t first = 0; first < n; first += static_cast<std::int64_t>(kBatchEntries)) {
          const std::int64_t count = std::min<std::int64_t>(static_cast<std::int64_t>(kBatchEntries), n - first);
          auto entries = guarded(path, "reading", [&] { return read_entries(old.tables, nullptr, first, count); });
          for (GraphRecord& e : entries) {
            w.existing.emplace_back(e.name, e.content_hash);
            append(std::move(e));
          }
        }
        w.write_step(temporary, "writing", [&] { w.commit(); });
      },
      [&] { w.abandon(); });
  // The open file's journal follows it.
  w.write_step(path, "resuming", [&] { move_write_journal(vfd_descriptor(w.file), path); });
}

CollectionWriter::~CollectionWriter() {
  try {
    close();
  } catch (...) {
    // documented: errors are swallowed here, close() reports them
  }
}

const std::vector<std::pair<std::string, std::uint64_t>>& CollectionWriter::existing() const { return impl_->existing; }

std::int64_t CollectionWriter::size() const { return impl_->written + impl_->buffered; }

void CollectionWriter::append(GraphRecord entry) {
  Impl& w = *impl_;
  if (w.file.getId() == H5I_INVALID_HID)
    throw InvalidArgument(w.path.string() + ": append after close() or a failed write");
  check_entry(entry, w.path);
  if (entry.signature.empty()) entry.signature.assign(kSignatureLength, std::numeric_limits<double>::quiet_NaN());
  const std::vector<Dataset>& specs = datasets();
  // The values first, which tell the rows the entry adds to each part.
  std::array<std::int64_t, kPartCount> added{};
  for (std::size_t d = 0; d < specs.size(); ++d) {
    if (specs[d].is_offsets()) continue;
    Table& t = w.tables.table[d];
    const std::size_t before = t.pending.size();
    specs[d].put(entry, t.pending);
    added[specs[d].part] = static_cast<std::int64_t>((t.pending.size() - before) / t.row_bytes());
  }
  for (std::size_t d = 0; d < specs.size(); ++d) {
    const Dataset& spec = specs[d];
    if (!spec.is_offsets()) continue;
    // The entry's own offsets into the part it indexes, from 0.
    const std::vector<std::int64_t> local =
        spec.local != nullptr ? entry.*spec.local : std::vector<std::int64_t>{0, added[spec.indexes]};
    for (std::int64_t r = 1; r <= added[spec.part]; ++r) {
      const std::int64_t end = w.totals[spec.indexes] + (local.empty() ? 0 : local[static_cast<std::size_t>(r)]);
      append_bytes(w.tables.table[d].pending, &end, sizeof end);
    }
  }
  for (int p = 0; p < kPartCount; ++p) w.totals[p] += added[p];
  if (++w.buffered >= static_cast<std::int64_t>(kBatchEntries))
    w.write_step(w.path, "writing", [&] { w.write_batch(); });
}

void CollectionWriter::checkpoint() {
  Impl& w = *impl_;
  if (w.file.getId() == H5I_INVALID_HID)
    throw InvalidArgument(w.path.string() + ": checkpoint after close() or a failed write");
  w.write_step(w.path, "writing", [&] { w.commit(); });
}

void CollectionWriter::close() {
  Impl& w = *impl_;
  if (w.file.getId() == H5I_INVALID_HID) return;
  checkpoint();
  w.write_step(w.path, "closing", [&] {
    w.tables = Tables{};
    w.file.close();
  });
}

// ---------------------------------------------------------------------------
// Query file

namespace {

/// Version of the query file's layout (its attribute `layout`).
constexpr int kQueryFileLayout = 1;
/// The collection's datasets a query file copies (with the offsets of their
/// part): what graph matching reads of a candidate.
constexpr std::array<const char*, 3> kQueryGraphDatasets = {"nodes", "node_attr", "edges"};
/// Entries a query file is written from per read of the collection.
constexpr std::int64_t kQueryWriteBatch = 512;

/// The offsets dataset of `part` in a query file.
const char* query_offsets_name(Part part) { return part == kNode ? "node_offset" : "edge_offset"; }

/// A contiguous, unfiltered dataset of `rows` rows of `spec`'s type and columns.
Table create_contiguous(H5::H5File& file, const char* name, const Dataset& spec, hsize_t rows) {
  Table t;
  t.type = *spec.type;
  t.width = spec.columns.size();
  const hsize_t dims[2] = {rows, t.width};
  t.dataset = file.createDataSet(name, t.type, H5::DataSpace(t.rank(), dims));
  t.rows = rows;
  return t;
}

/// Writes `n` rows from `data` at row `first` of a table of fixed size.
void write_rows(const Table& t, const void* data, hsize_t first, hsize_t n) {
  if (n == 0) return;
  const auto [file_space, memory_space] = t.select_rows(first, n);
  t.dataset.write(data, t.type, memory_space, file_space);
}

std::int64_t read_int_attribute(const H5::H5Object& object, const char* name) {
  std::int64_t value = -1;
  if (object.attrExists(name)) object.openAttribute(name).read(H5::PredType::NATIVE_INT64, &value);
  return value;
}

void write_int_attribute(H5::H5Object& object, const char* name, std::int64_t value) {
  object.createAttribute(name, H5::PredType::NATIVE_INT64, H5::DataSpace(H5S_SCALAR))
      .write(H5::PredType::NATIVE_INT64, &value);
}

/// The rows of the contiguous dataset `t` of the file `path`, of the native
/// type `type`, mapped read-only (nullptr when it has none); the mapping
/// lasts while a copy of the pointer does.
std::shared_ptr<const char> map_rows(const fs::path& path, const Table& t, const H5::PredType& type) {
  const std::size_t bytes = static_cast<std::size_t>(t.rows) * t.row_bytes();
  if (bytes == 0) return nullptr;
  const haddr_t address = H5Dget_offset(t.dataset.getId());
  if (address == HADDR_UNDEF || !(t.dataset.getDataType() == type))
    fail(path, t.dataset.getObjName() + " is not contiguous or not of the native type");
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) fail(path, std::string("cannot open: ") + std::strerror(errno));
  struct stat status {};
  const auto page = static_cast<haddr_t>(::sysconf(_SC_PAGESIZE));
  const haddr_t start = address / page * page;
  const std::size_t length = bytes + static_cast<std::size_t>(address - start);
  if (::fstat(fd, &status) != 0 || static_cast<haddr_t>(status.st_size) < address + bytes) {  // else SIGBUS
    ::close(fd);
    fail(path, "shorter than its dataset " + t.dataset.getObjName() + " (truncated?)");
  }
  void* map = ::mmap(nullptr, length, PROT_READ, MAP_SHARED, fd, static_cast<off_t>(start));
  const int error = errno;
  ::close(fd);
  if (map == MAP_FAILED) fail(path, "cannot map " + t.dataset.getObjName() + ": " + std::strerror(error));
  const std::shared_ptr<const char> mapping(static_cast<const char*>(map),
                                            [length](const char* p) { ::munmap(const_cast<char*>(p), length); });
  return {mapping, mapping.get() + (address - start)};
}

}  // namespace

struct QueryFile::Impl {
  fs::path path;
  H5::H5File file;
  std::vector<std::int64_t> row_of;
  std::array<std::vector<std::int64_t>, kPartCount> offsets;  ///< kNode and kEdge: #entries + 1
  Table signature, index;
  std::array<Table, kQueryGraphDatasets.size()> graph;
  /// The rows of `signature` and `graph`, mapped (map_rows).
  std::shared_ptr<const char> signature_rows;
  std::array<std::shared_ptr<const char>, kQueryGraphDatasets.size()> graph_rows;
};

QueryFile::QueryFile() : impl_(std::make_unique<Impl>()) {}
QueryFile::QueryFile(QueryFile&&) noexcept = default;
QueryFile& QueryFile::operator=(QueryFile&&) noexcept = default;
QueryFile::~QueryFile() = default;

fs::path QueryFile::path_of(const fs::path& collection) {
  // Beside the file a link to the collection names, whichever name is used.
  fs::path path = fs::is_symlink(collection) ? fs::weakly_canonical(collection) : collection;
  return path.replace_extension(".query.h5");
}

void QueryFile::write(const CollectionReader& collection, const double* rows, const std::vector<std::int64_t>& row_of,
                      const std::vector<char>& saved_index) {
  const CollectionReader::Impl& c = *collection.impl_;
  const fs::path path = path_of(c.path);
  fs::path temporary = path;
  temporary += ".partial";
  const EntryOffsets& offsets = c.all_offsets();
  const Dataset& signature_spec = datasets()[dataset_index("signature")];
  const auto write_file = [&] {
    H5::H5File file(temporary.string(), H5F_ACC_TRUNC);
    const int layout = kQueryFileLayout;
    file.createAttribute("layout", H5::PredType::NATIVE_INT, H5::DataSpace(H5S_SCALAR))
        .write(H5::PredType::NATIVE_INT, &layout);
    write_int_attribute(file, "collection_count", c.snapshot.size);
    write_string_attribute(file, "collection_created", c.snapshot.provenance.created);
    write_rows(create_contiguous(file, "signature", signature_spec, row_of.size()), rows, 0, row_of.size());
    const Dataset rows_spec = make_dataset("signature_row", type_of<std::int64_t>(), kEntry);
    write_rows(create_contiguous(file, "signature_row", rows_spec, row_of.size()), row_of.data(), 0, row_of.size());
    const Dataset bytes_spec = make_dataset("index", type_of<char>(), kEntry);
    write_rows(create_contiguous(file, "index", bytes_spec, saved_index.size()), saved_index.data(), 0,
               saved_index.size());
    for (const Part part : {kNode, kEdge}) {
      const std::vector<std::int64_t>& offset = offsets[part];
      const Dataset spec = make_dataset(query_offsets_name(part), type_of<std::int64_t>(), kEntry);
      write_rows(create_contiguous(file, spec.name, spec, offset.size()), offset.data(), 0, offset.size());
    }
    std::vector<Table> graph;
    for (const char* name : kQueryGraphDatasets) {
      const Dataset& spec = datasets()[dataset_index(name)];
      graph.push_back(create_contiguous(file, name, spec, static_cast<hsize_t>(offsets[spec.part].back())));
      if (!spec.columns.empty()) write_text_attribute(graph.back().dataset, "columns", spec.columns, false);
    }
    for (std::int64_t first = 0; first < c.snapshot.size; first += kQueryWriteBatch) {
      const std::int64_t n = std::min(kQueryWriteBatch, c.snapshot.size - first);
      const std::vector<GraphRecord> entries = read_entries(c.tables, &offsets, first, n);
      for (std::size_t d = 0; d < kQueryGraphDatasets.size(); ++d) {
        const Dataset& spec = datasets()[dataset_index(kQueryGraphDatasets[d])];
        std::vector<char> data;
        for (const GraphRecord& e : entries) spec.put(e, data);
        const auto row0 = static_cast<hsize_t>(offsets[spec.part][static_cast<std::size_t>(first)]);
        write_rows(graph[d], data.data(), row0, data.size() / graph[d].row_bytes());
      }
    }
    file.close();
  };
  replace_file(
      path, temporary, [&] { guarded(temporary, "writing", write_file); }, [] {});
}

std::optional<QueryFile> QueryFile::open(const CollectionReader& collection) {
  const CollectionReader::Impl& c = *collection.impl_;
  const fs::path path = path_of(c.path);
  if (!fs::exists(path)) return std::nullopt;
  if (H5Fis_hdf5(path.c_str()) <= 0) fail(path, "not an HDF5 file (remove it: queries then read the collection)");
  QueryFile q;
  Impl& f = *q.impl_;
  f.path = path;
  const bool current = guarded(path, "opening", [&] {
    f.file = H5::H5File(path.string(), H5F_ACC_RDONLY);
    return layout_version(f.file) == kQueryFileLayout &&
           read_int_attribute(f.file, "collection_count") == c.snapshot.size &&
           read_string_attribute(f.file, "collection_created") == c.snapshot.provenance.created;
  });
  if (!current) return std::nullopt;
  guarded(path, "reading", [&] {
    const Dataset& signature_spec = datasets()[dataset_index("signature")];
    f.signature = open_table(f.file, "signature", signature_spec);
    const Table rows = open_table(f.file, "signature_row", make_dataset("", type_of<std::int64_t>(), kEntry));
    f.row_of = rows.read_vector<std::int64_t>(0, rows.rows);
    if (f.signature.rows != rows.rows || !std::is_sorted(f.row_of.begin(), f.row_of.end()) ||
        (!f.row_of.empty() && (f.row_of.front() < 0 || f.row_of.back() >= c.snapshot.size)))
      throw H5::DataSetIException("read", "signature_row is not increasing entries of the signature rows");
    f.index = open_table(f.file, "index", make_dataset("", type_of<char>(), kEntry));
    for (std::size_t d = 0; d < kQueryGraphDatasets.size(); ++d) {
      const Dataset& spec = datasets()[dataset_index(kQueryGraphDatasets[d])];
      f.graph[d] = open_table(f.file, spec.name, spec);
      const Table offsets =
          open_table(f.file, query_offsets_name(spec.part), make_dataset("", type_of<std::int64_t>(), kEntry));
      if (offsets.rows != static_cast<hsize_t>(c.snapshot.size) + 1)
        throw H5::DataSetIException("read", std::string(query_offsets_name(spec.part)) + " is not #entries + 1 long");
      f.offsets[spec.part] = offsets.read_vector<std::int64_t>(0, offsets.rows);
      check_offsets(f.offsets[spec.part], f.graph[d].rows, query_offsets_name(spec.part));
    }
  });
  f.signature_rows = map_rows(path, f.signature, *datasets()[dataset_index("signature")].type);
  for (std::size_t d = 0; d < kQueryGraphDatasets.size(); ++d)
    f.graph_rows[d] = map_rows(path, f.graph[d], *datasets()[dataset_index(kQueryGraphDatasets[d])].type);
  return q;
}

std::shared_ptr<const double> QueryFile::rows() const {
  return {impl_->signature_rows, reinterpret_cast<const double*>(impl_->signature_rows.get())};
}

const std::vector<std::int64_t>& QueryFile::row_of() const { return impl_->row_of; }

std::vector<char> QueryFile::saved_index() const {
  return guarded(impl_->path, "reading", [&] { return impl_->index.read_vector<char>(0, impl_->index.rows); });
}

std::vector<GraphRecord> QueryFile::graphs(const std::vector<std::int64_t>& entries) const {
  const Impl& f = *impl_;
  const Dataset& signature_spec = datasets()[dataset_index("signature")];
  std::vector<GraphRecord> out(entries.size());
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const auto at = std::lower_bound(f.row_of.begin(), f.row_of.end(), entries[k]);
    if (at == f.row_of.end() || *at != entries[k])
      throw InvalidArgument(f.path.string() + ": entry " + std::to_string(entries[k]) + " has no signature row");
    GraphRecord& g = out[k];
    g.ok = true;
    const auto packed = static_cast<std::size_t>(at - f.row_of.begin());
    signature_spec.take(g, f.signature_rows.get() + packed * f.signature.row_bytes(), f.signature.columns());
    for (std::size_t d = 0; d < kQueryGraphDatasets.size(); ++d) {
      const Dataset& spec = datasets()[dataset_index(kQueryGraphDatasets[d])];
      const auto e = static_cast<std::size_t>(entries[k]);
      const auto first = static_cast<std::size_t>(f.offsets[spec.part][e]);
      const auto n = static_cast<std::size_t>(f.offsets[spec.part][e + 1]) - first;
      spec.take(g, f.graph_rows[d].get() + first * f.graph[d].row_bytes(), n * f.graph[d].columns());
    }
  }
  return out;
}

}  // namespace reebkit

#include "reebkit/store/write_journal.h"

#include "reebkit/core/error.h"
#include "reebkit/io/content_hash.h"

#include <H5FDpublic.h>
#include <H5FDsec2.h>
#include <H5Ppublic.h>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <mutex>
#include <string>
#include <string_view>
#include <type_traits>
#include <unordered_map>
#include <vector>

namespace reebkit {

namespace fs = std::filesystem;

namespace {

/// The journal's record: this header, then `size` bytes to write at `address`.
struct RecordHeader {
  std::uint64_t magic;
  std::uint64_t address;
  std::uint64_t size;
  /// record_checksum of the address, the size and the bytes.
  std::uint64_t checksum;
};
constexpr std::uint64_t kMagic = 0x6c6e72756f6a6272ULL;  // "rbjournl"

/// hash_bytes of the address and the size, mixed with hash_bytes of the
/// bytes (hashed where they lie: every write of the collection passes here).
std::uint64_t record_checksum(std::uint64_t address, std::uint64_t size, const void* bytes) {
  const std::uint64_t place[2] = {address, size};
  const std::uint64_t where = hash_bytes({reinterpret_cast<const char*>(place), sizeof place});
  return where ^ (hash_bytes({static_cast<const char*>(bytes), size}) * 0x9e3779b97f4a7c15ULL);
}

/// Writes all of `bytes` at `offset`; false on a failure (errno set).
bool write_all(int fd, const void* bytes, std::size_t size, off_t offset) {
  const auto* p = static_cast<const char*>(bytes);
  while (size > 0) {
    const ssize_t n = ::pwrite(fd, p, size, offset);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= static_cast<std::size_t>(n);
    offset += n;
  }
  return true;
}

// The driver: HDF5 hands each call the H5FD_t it got from open(), which is
// the first member of Journaled.
struct Journaled {
  H5FD_t public_part;  // filled by HDF5
  H5FD_t* inner = nullptr;
  int journal = -1;  // -1: opened read-only
  std::string journal_path;
  /// A write failed: later writes (HDF5 retrying them on close) are not
  /// recorded, so that the record stays the write the file was left in.
  bool failed = false;
  /// stop_write_journal was called: later writes are not recorded.
  bool stopped = false;
  int descriptor = -1;  // sec2's
};

/// The open journaled files by their sec2 descriptor, for stop_write_journal.
std::mutex open_files_mutex;
std::unordered_map<int, Journaled*> open_files;

Journaled* self(H5FD_t* file) { return reinterpret_cast<Journaled*>(file); }
const Journaled* self(const H5FD_t* file) { return reinterpret_cast<const Journaled*>(file); }

H5FD_t* open_journaled(const char* name, unsigned flags, hid_t, haddr_t maxaddr) {
  const hid_t sec2 = H5Pcreate(H5P_FILE_ACCESS);
  if (sec2 < 0) return nullptr;
  H5Pset_fapl_sec2(sec2);
  H5FD_t* inner = H5FDopen(name, flags, sec2, maxaddr);
  H5Pclose(sec2);
  if (inner == nullptr) return nullptr;
  auto* file = new Journaled;
  file->inner = inner;
  if ((flags & H5F_ACC_RDWR) != 0) {
    file->journal_path = journal_path(name).string();
    file->journal = ::open(file->journal_path.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (file->journal < 0 || ::flock(file->journal, LOCK_EX | LOCK_NB) != 0) {
      if (file->journal >= 0) ::close(file->journal);
      H5FDclose(inner);
      delete file;
      return nullptr;
    }
  }
  void* handle = nullptr;
  if (H5FDget_vfd_handle(inner, H5P_DEFAULT, &handle) >= 0 && handle != nullptr) {
    file->descriptor = *static_cast<int*>(handle);
    const std::lock_guard<std::mutex> lock(open_files_mutex);
    open_files[file->descriptor] = file;
  }
  return &file->public_part;
}

herr_t close_journaled(H5FD_t* h) {
  Journaled* file = self(h);
  if (file->descriptor >= 0) {
    const std::lock_guard<std::mutex> lock(open_files_mutex);
    open_files.erase(file->descriptor);
  }
  const herr_t status = H5FDclose(file->inner);
  if (file->journal >= 0) {
    // Closed whole: no write to complete. After a failed write the record
    // stays, for the next open to complete it (complete_interrupted_write).
    if (status >= 0 && !file->failed) ::unlink(file->journal_path.c_str());
    ::close(file->journal);
  }
  delete file;
  return status;
}

herr_t write_journaled(H5FD_t* h, H5FD_mem_t type, hid_t dxpl, haddr_t address, size_t size, const void* bytes) {
  Journaled* file = self(h);
  if (file->journal >= 0 && !file->failed && !file->stopped) {
    const RecordHeader header{kMagic, address, size, record_checksum(address, size, bytes)};
    if (!write_all(file->journal, &header, sizeof header, 0) ||
        !write_all(file->journal, bytes, size, static_cast<off_t>(sizeof header))) {
      file->failed = true;
      return -1;
    }
  }
  const herr_t status = H5FDwrite(file->inner, type, dxpl, address, size, bytes);
  if (status < 0) file->failed = true;
  return status;
}

herr_t read_journaled(H5FD_t* h, H5FD_mem_t type, hid_t dxpl, haddr_t address, size_t size, void* bytes) {
  return H5FDread(self(h)->inner, type, dxpl, address, size, bytes);
}

int compare_journaled(const H5FD_t* a, const H5FD_t* b) { return H5FDcmp(self(a)->inner, self(b)->inner); }

// HDF5 asks before the file is open (h null): the features of sec2 (those
// its query gives in HDF5 1.10), SWMR included, so that the files come out
// as sec2 lays them out.
herr_t query_journaled(const H5FD_t* h, unsigned long* flags) {
  if (h != nullptr) return H5FDquery(self(h)->inner, flags) < 0 ? -1 : 0;
  *flags = H5FD_FEAT_AGGREGATE_METADATA | H5FD_FEAT_ACCUMULATE_METADATA | H5FD_FEAT_DATA_SIEVE |
           H5FD_FEAT_AGGREGATE_SMALLDATA | H5FD_FEAT_POSIX_COMPAT_HANDLE | H5FD_FEAT_SUPPORTS_SWMR_IO |
           H5FD_FEAT_DEFAULT_VFD_COMPATIBLE;
  return 0;
}

haddr_t get_eoa_journaled(const H5FD_t* h, H5FD_mem_t type) {
  return H5FDget_eoa(const_cast<H5FD_t*>(self(h)->inner), type);
}

herr_t set_eoa_journaled(H5FD_t* h, H5FD_mem_t type, haddr_t address) {
  return H5FDset_eoa(self(h)->inner, type, address);
}

haddr_t get_eof_journaled(const H5FD_t* h, H5FD_mem_t type) {
  return H5FDget_eof(const_cast<H5FD_t*>(self(h)->inner), type);
}

herr_t get_handle_journaled(H5FD_t* h, hid_t fapl, void** handle) {
  return H5FDget_vfd_handle(self(h)->inner, fapl, handle);
}

herr_t flush_journaled(H5FD_t* h, hid_t dxpl, hbool_t closing) { return H5FDflush(self(h)->inner, dxpl, closing); }

herr_t truncate_journaled(H5FD_t* h, hid_t dxpl, hbool_t closing) {
  return H5FDtruncate(self(h)->inner, dxpl, closing);
}

herr_t lock_journaled(H5FD_t* h, hbool_t read_write) { return H5FDlock(self(h)->inner, read_write); }

herr_t unlock_journaled(H5FD_t* h) { return H5FDunlock(self(h)->inner); }

H5FD_class_t make_class() {
  H5FD_class_t c{};
  c.name = "reebkit_write_journal";
  c.maxaddr = (haddr_t{1} << 63) - 1;  // as sec2: the largest off_t
  c.fc_degree = H5F_CLOSE_WEAK;
  c.open = open_journaled;
  c.close = close_journaled;
  c.cmp = compare_journaled;
  c.query = query_journaled;
  c.get_eoa = get_eoa_journaled;
  c.set_eoa = set_eoa_journaled;
  c.get_eof = get_eof_journaled;
  c.get_handle = get_handle_journaled;
  c.read = read_journaled;
  c.write = write_journaled;
  c.flush = flush_journaled;
  c.truncate = truncate_journaled;
  c.lock = lock_journaled;
  c.unlock = unlock_journaled;
  const H5FD_mem_t free_lists[H5FD_MEM_NTYPES] = H5FD_FLMAP_DICHOTOMY;  // as sec2
  std::copy(std::begin(free_lists), std::end(free_lists), std::begin(c.fl_map));
  return c;
}

hid_t driver_id() {
  static const H5FD_class_t kClass = make_class();
  static const hid_t id = H5FDregister(&kClass);
  return id;
}

}  // namespace

fs::path journal_path(const fs::path& path) {
  fs::path journal = path;
  journal += ".journal";
  return journal;
}

static_assert(std::is_same_v<hid_t, std::int64_t>, "use_write_journal takes an HDF5 1.10 hid_t");

void use_write_journal(std::int64_t access) {
  const hid_t id = driver_id();
  if (id < 0 || H5Pset_driver(access, id, nullptr) < 0)
    throw Error("HDF5: cannot register or set the write-journal file driver");
}

void stop_write_journal(int descriptor) {
  const std::lock_guard<std::mutex> lock(open_files_mutex);
  const auto found = open_files.find(descriptor);
  if (found != open_files.end()) found->second->stopped = true;
}

void move_write_journal(int descriptor, const fs::path& renamed) {
  const std::lock_guard<std::mutex> lock(open_files_mutex);
  const auto found = open_files.find(descriptor);
  if (found == open_files.end() || found->second->journal < 0) return;
  Journaled& file = *found->second;
  const std::string moved = journal_path(renamed).string();
  if (::rename(file.journal_path.c_str(), moved.c_str()) != 0)
    throw Error(renamed.string() + ": cannot move its write journal " + file.journal_path + " to " + moved + ": " +
                std::strerror(errno));
  file.journal_path = moved;
}

bool complete_interrupted_write(const fs::path& path) {
  const fs::path journal = journal_path(path);
  const int fd = ::open(journal.c_str(), O_RDWR | O_CLOEXEC);
  if (fd < 0) return false;  // none: the last writer closed the file, or none wrote it
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) return false;  // its writer is alive
  const auto failed = [&](const std::string& what, int error) {
    throw Error(path.string() + ": completing the write its last writer was killed in: " + what + ": " +
                std::strerror(error));
  };
  RecordHeader header{};
  bool whole = ::pread(fd, &header, sizeof header, 0) == static_cast<ssize_t>(sizeof header) && header.magic == kMagic;
  std::vector<char> bytes;
  if (whole) {
    const off_t end = ::lseek(fd, 0, SEEK_END);
    whole = end >= 0 && header.size <= static_cast<std::uint64_t>(end) - sizeof header;
  }
  if (whole) {
    bytes.resize(header.size);
    whole = ::pread(fd, bytes.data(), bytes.size(), static_cast<off_t>(sizeof header)) ==
                static_cast<ssize_t>(bytes.size()) &&
            record_checksum(header.address, header.size, bytes.data()) == header.checksum;
  }
  if (whole) {
    const int file = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (file < 0) failed("cannot open it for writing", errno);
    const bool written =
        write_all(file, bytes.data(), bytes.size(), static_cast<off_t>(header.address)) && ::fsync(file) == 0;
    const int error = errno;
    ::close(file);
    if (!written) failed("cannot write it", error);
  }
  // A torn record is ignored: the write it preceded had not started.
  if (::unlink(journal.c_str()) != 0 && errno != ENOENT) failed("cannot remove " + journal.string(), errno);
  return whole;
}

}  // namespace reebkit

// A guard against torn writes: an HDF5 file driver that copies each write
// into a journal beside the file (PATH.journal) before it makes the write.
//
// The collection writer (collection_file.cpp) relies on HDF5's SWMR mode,
// whose ordered metadata writes leave a coherent file between any two of
// its writes. A process killed inside a write breaks that: the kernel
// copies a write into the file a page at a time and stops at a page
// boundary when the process dies, so a metadata block that spans two pages
// (a dataset's object header, an index block of its chunks) can be left
// half old, half new, and the dataset no longer opens. Here each write is
// first recorded whole, with a checksum, as the journal's only record; a
// write the writer was killed in is then completed from the journal
// (complete_interrupted_write), which puts the file back between two
// writes. A torn record (the kill came while it was written) fails its
// checksum and is ignored: the file write it preceded had not started.
//
// The driver is sec2 underneath and stores nothing of its own in the file:
// h5py and every other HDF5 reader open the file as any other. The journal
// is removed when the file is closed, and holds one write (the largest is a
// chunk of a dataset) while it is open. It is not synced: it guards against
// a killed process, whose writes the operating system keeps, not against a
// power loss in the middle of a write.
#pragma once

#include <cstdint>
#include <filesystem>

namespace reebkit {

/// The journal of the file `path`: `path` + ".journal".
std::filesystem::path journal_path(const std::filesystem::path& path);

/// Sets the file driver of the HDF5 file access property list `access` (its
/// hid_t) to the journaling one. A file opened for writing with it takes PATH.journal
/// (created; a second writer is refused) for as long as it is open.
void use_write_journal(std::int64_t access);

/// Stops recording the writes of the journaled file whose sec2 file
/// descriptor (H5Fget_vfd_handle) is `descriptor`: for a writer that gives
/// up on a file and sends its last writes nowhere, whose record must stay
/// the last write the file got. The journal is still removed when the file
/// closes, unless a write to the file failed (its record completes it).
void stop_write_journal(int descriptor);

/// The journaled file whose sec2 file descriptor is `descriptor` was renamed
/// to `renamed`: its journal follows it (renamed + ".journal"). Throws Error
/// naming `renamed` when the journal cannot be moved.
void move_write_journal(int descriptor, const std::filesystem::path& renamed);

/// When PATH.journal is left by a writer that died (no process holds it),
/// writes its record into `path` where the record is whole, syncs `path`,
/// and removes the journal. Returns whether a write was completed. Does
/// nothing while the writer is alive. Throws Error naming `path` when the
/// journal cannot be read or the file cannot be written.
bool complete_interrupted_write(const std::filesystem::path& path);

}  // namespace reebkit

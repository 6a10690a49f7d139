// Preloaded (LD_PRELOAD) into tests/store/crash_writer by the torn-write
// test: the TEAR_WRITE_AT-th pwrite of the process (from 1) writes its bytes
// only up to the first page boundary they cross, nothing if they cross none,
// and the process exits at once. That is the file a process killed inside a
// write leaves: the kernel copies a write a page at a time and stops at a
// page boundary when the process dies.
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdlib.h>
#include <sys/types.h>
#include <unistd.h>

typedef ssize_t (*pwrite_fn)(int, const void*, size_t, off_t);

static long writes = 0;

static ssize_t torn_pwrite(const char* name, int fd, const void* bytes, size_t size, off_t offset) {
  const pwrite_fn real = (pwrite_fn)dlsym(RTLD_NEXT, name);
  const char* at = getenv("TEAR_WRITE_AT");
  if (at != NULL && ++writes == atol(at)) {
    const size_t to_boundary = 4096 - (size_t)(offset % 4096);
    if (to_boundary < size) real(fd, bytes, to_boundary, offset);
    _exit(9);
  }
  return real(fd, bytes, size, offset);
}

ssize_t pwrite(int fd, const void* bytes, size_t size, off_t offset) {
  return torn_pwrite("pwrite", fd, bytes, size, offset);
}

ssize_t pwrite64(int fd, const void* bytes, size_t size, off_t offset) {
  return torn_pwrite("pwrite64", fd, bytes, size, offset);
}

// The writer that tests/store/collection_file_test.cpp kills: appends
// make_entry(0), make_entry(1), ... to the collection file argv[1], makes a
// checkpoint after each entry i with checkpoint_after(i), writes each
// committed count to stdout as 8 raw bytes (0 once the file is set up), and
// runs until it is killed.
#include "store/collection_entries.h"

#include <unistd.h>

#include <cstdint>
#include <exception>

int main(int argc, char** argv) {
  using namespace reebkit;
  if (argc != 2) return 2;
  const auto report = [](std::int64_t committed) {
    if (::write(1, &committed, sizeof committed) != sizeof committed) ::_exit(3);
  };
  try {
    CollectionWriter writer(argv[1], test::test_provenance(), false);
    report(0);
    for (std::int64_t i = 0;; ++i) {
      writer.append(test::make_entry(i));
      if (test::checkpoint_after(i)) {
        writer.checkpoint();
        report(i + 1);
      }
    }
  } catch (const std::exception&) {
    return 2;
  }
}

// tirectl schema: levels/schema.json as the parameter table generates it (tire/io/level_format.h).
#include <iostream>

#include "commands.h"
#include "tire/io/file_io.h"
#include "tire/io/level_format.h"

namespace tirectl {

namespace {

// The first line where two texts differ (1-based), both lines shown.
std::string first_difference(const std::string& a, const std::string& b) {
  std::size_t line = 1, start = 0;
  std::size_t i = 0;
  for (; i < a.size() && i < b.size() && a[i] == b[i]; ++i)
    if (a[i] == '\n') ++line, start = i + 1;
  const auto line_at = [start](const std::string& s) {
    const std::size_t end = s.find('\n', start);
    return start >= s.size() ? std::string("(end of file)")
                             : s.substr(start, end == std::string::npos ? end : end - start);
  };
  return "line " + std::to_string(line) + ": the file has\n  " + line_at(a) +
         "\nand the table generates\n  " + line_at(b);
}

}  // namespace

int schema(const SchemaOptions& options) {
  const std::string file = tire::printable(options.file);
  std::string error;
  const auto current = tire::read_file(options.file, 16u << 20, error);
  if (!current) {
    std::cerr << file << ": " << error << "\n";
    return 2;
  }
  const tire::SchemaGeneration generated = tire::generate_level_schema(*current);
  if (!generated.text) {
    std::cerr << file << ": not the level schema: " << generated.error << "\n";
    return 2;
  }
  const bool same = *generated.text == *current;
  if (options.check) {
    if (same) {
      std::cout << file << ": up to date with the parameter table\n";
      return 0;
    }
    std::cerr << file
              << ": differs from what the parameter table (engine/tire/include/tire/tire/parameters.h) "
              << "generates, first at " << first_difference(*current, *generated.text)
              << "\nRegenerate it with: tirectl schema --write " << file << "\n";
    return 1;
  }
  if (options.write) {
    if (same) {
      std::cout << file << ": already up to date\n";
      return 0;
    }
    if (!tire::write_file_atomically(options.file, *generated.text, error)) {
      std::cerr << file << ": " << error << "\n";
      return 2;
    }
    std::cout << file << ": rewritten from the parameter table\n";
    return 0;
  }
  std::cout << *generated.text;
  return 0;
}

}  // namespace tirectl

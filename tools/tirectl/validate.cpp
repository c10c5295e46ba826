#include <iostream>

#include "commands.h"
#include "tire/io/file_io.h"
#include "tire/level.h"

namespace tirectl {

int validate(const std::vector<std::string>& files) {
  int failed = 0;
  for (const std::string& file : files) {
    const tire::LevelOpen load = tire::open_level_file(file);
    for (const std::string& error : load.errors) std::cerr << error << "\n";
    if (load.level)
      std::cout << tire::printable(file) << ": ok\n";
    else
      ++failed;
  }
  return failed == 0 ? 0 : 2;
}

}  // namespace tirectl

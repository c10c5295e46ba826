// Files written safely (tire/io/file_io.h): what write_file_atomically refuses, what it writes
// through, what it keeps, and write_new_file_atomically's numbered names.
#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "tire/io/file_io.h"

namespace fs = std::filesystem;
using tire::write_file_atomically;

namespace {

// A fresh folder of the test's own, removed at the end.
struct Folder {
  fs::path path;
  explicit Folder(const std::string& name)
      : path(fs::temp_directory_path() / ("tire-file-io-" + name + "-" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~Folder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  fs::path operator/(const std::string& name) const { return path / name; }
};

std::string contents_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

void put(const fs::path& file, const std::string& text) { std::ofstream(file, std::ios::binary) << text; }

mode_t mode_of(const fs::path& file) {
  struct stat st {};
  REQUIRE(::lstat(file.c_str(), &st) == 0);
  return st.st_mode;
}

std::set<std::string> names_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

}  // namespace

TEST_CASE("write_file_atomically writes a new file, then replaces it whole, leaving no temporary",
          "[unit][files]") {
  const Folder dir("new");
  const fs::path file = dir / "out.json";
  std::string error;
  REQUIRE(write_file_atomically(file, "first", error));
  CHECK(contents_of(file) == "first");
  const mode_t umask_now = ::umask(0);
  ::umask(umask_now);
  CHECK((mode_of(file) & 07777) == (0644 & ~umask_now));
  REQUIRE(write_file_atomically(file, "second, longer", error));
  CHECK(contents_of(file) == "second, longer");
  CHECK(names_in(dir.path) == std::set<std::string>{"out.json"});
}

TEST_CASE("an existing file keeps its mode", "[unit][files]") {
  const Folder dir("mode");
  for (const mode_t mode : {mode_t{0600}, mode_t{0640}, mode_t{0755}}) {
    const fs::path file = dir / (std::to_string(mode) + ".json");
    put(file, "old");
    REQUIRE(::chmod(file.c_str(), mode) == 0);
    std::string error;
    REQUIRE(write_file_atomically(file, "new", error));
    CHECK(contents_of(file) == "new");
    CHECK((mode_of(file) & 07777) == mode);
  }
}

TEST_CASE("a symbolic link is written through: its file gets the contents, the link stays", "[unit][files]") {
  const Folder dir("link");
  fs::create_directories(dir / "real");
  const fs::path real = dir / "real" / "level.json";
  put(real, "old");
  REQUIRE(::chmod(real.c_str(), 0600) == 0);
  const fs::path link = dir / "link.json";
  fs::create_symlink("real/level.json", link);  // relative to the link's folder
  const fs::path link_to_link = dir / "link2.json";
  fs::create_symlink(fs::absolute(link), link_to_link);
  std::string error;
  REQUIRE(write_file_atomically(link, "through the link", error));
  CHECK(fs::is_symlink(link));
  CHECK(fs::read_symlink(link) == "real/level.json");
  CHECK(contents_of(real) == "through the link");
  CHECK((mode_of(real) & 07777) == 0600);
  REQUIRE(write_file_atomically(link_to_link, "through two links", error));
  CHECK(fs::is_symlink(link_to_link));
  CHECK(fs::is_symlink(link));
  CHECK(contents_of(real) == "through two links");
  // The temporary went beside the file written, not beside the link, and is gone.
  CHECK(names_in(dir / "real") == std::set<std::string>{"level.json"});
  CHECK(names_in(dir.path) == std::set<std::string>{"link.json", "link2.json", "real"});

  SECTION("a dangling link's file is created") {
    const fs::path dangling = dir / "dangling.json";
    fs::create_symlink("real/new.json", dangling);
    REQUIRE(write_file_atomically(dangling, "created", error));
    CHECK(fs::is_symlink(dangling));
    CHECK(contents_of(dir / "real" / "new.json") == "created");
  }
  SECTION("a loop of links is refused") {
    fs::create_symlink("b", dir / "a");
    fs::create_symlink("a", dir / "b");
    CHECK_FALSE(write_file_atomically(dir / "a", "x", error));
    CHECK(error.find("too many levels of symbolic links") != std::string::npos);
    CHECK(fs::is_symlink(dir / "a"));
  }
}

TEST_CASE("a FIFO is refused and stays a FIFO", "[unit][files]") {
  const Folder dir("fifo");
  const fs::path fifo = dir / "pipe";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  std::string error;
  CHECK_FALSE(write_file_atomically(fifo, "x", error));
  CHECK(error == "cannot write " + fifo.string() + ": it is a FIFO, not a regular file");
  CHECK(S_ISFIFO(mode_of(fifo)));
  CHECK(tire::check_output_file(fifo) == error);
  // Through a link too, and the link names where it leads.
  const fs::path link = dir / "link";
  fs::create_symlink(fifo, link);
  CHECK_FALSE(write_file_atomically(link, "x", error));
  CHECK(error == "cannot write " + link.string() + " (a symbolic link to " + fifo.string() +
                     "): it is a FIFO, not a regular file");
  CHECK(S_ISFIFO(mode_of(fifo)));
  CHECK(names_in(dir.path) == std::set<std::string>{"link", "pipe"});
}

TEST_CASE("a directory and a device are refused", "[unit][files]") {
  const Folder dir("dir");
  fs::create_directories(dir / "sub");
  put(dir / "sub" / "kept", "kept");
  std::string error;
  CHECK_FALSE(write_file_atomically(dir / "sub", "x", error));
  CHECK(error == "cannot write " + (dir / "sub").string() + ": it is a directory, not a regular file");
  CHECK(fs::is_directory(dir / "sub"));
  CHECK(contents_of(dir / "sub" / "kept") == "kept");
  // A device is judged without writing (as root, a rename would replace /dev/null itself).
  CHECK(tire::check_output_file("/dev/null") ==
        "cannot write /dev/null: it is a character device, not a regular file");
  CHECK(tire::check_output_file(dir / "free.json").empty());
}

TEST_CASE("nothing planted where a temporary could go is opened or followed", "[unit][files]") {
  const Folder dir("planted");
  const fs::path victim = dir / "victim";
  put(victim, "untouched");
  fs::create_directories(dir / "out");
  const fs::path file = dir / "out" / "replay.json";
  // Links at the names this function once used (<file>.tmp.<pid>.<serial>) and at names of its
  // present form: none may be written through, removed or replaced.
  std::set<std::string> planted;
  for (int serial = 0; serial < 64; ++serial) {
    for (const std::string& name :
         {"replay.json.tmp." + std::to_string(::getpid()) + "." + std::to_string(serial),
          "replay.json.tmp-" + std::string(15, '0') + "0123456789abcdef"[serial % 16]}) {
      if (planted.insert(name).second) fs::create_symlink(victim, dir / "out" / name);
    }
  }
  std::string error;
  for (int i = 0; i < 64; ++i) REQUIRE(write_file_atomically(file, "written " + std::to_string(i), error));
  CHECK(contents_of(file) == "written 63");
  CHECK(contents_of(victim) == "untouched");
  std::set<std::string> expected = planted;
  expected.insert("replay.json");
  CHECK(names_in(dir / "out") == expected);
  for (const std::string& name : planted) CHECK(fs::is_symlink(dir / "out" / name));
}

TEST_CASE("a failed write says which file and why, and leaves no temporary", "[unit][files]") {
  const Folder dir("fail");
  std::string error;
  const fs::path missing = dir / "no-such-folder" / "out.json";
  CHECK_FALSE(write_file_atomically(missing, "x", error));
  CHECK(error.find("cannot write " + missing.string() + ": ") == 0);
  CHECK(error.find("No such file or directory") != std::string::npos);
  // A folder this user may not write to (root may write anywhere: only the message is checked there).
  fs::create_directories(dir / "read-only");
  const fs::path kept = dir / "read-only" / "kept.json";
  put(kept, "old and whole");
  REQUIRE(::chmod((dir / "read-only").c_str(), 0555) == 0);
  if (::geteuid() != 0) {
    CHECK_FALSE(write_file_atomically(kept, "new", error));
    CHECK(error.find("cannot write " + kept.string() + ": cannot create the temporary file ") == 0);
    CHECK(error.find("Permission denied") != std::string::npos);
    CHECK(contents_of(kept) == "old and whole");
    CHECK(names_in(dir / "read-only") == std::set<std::string>{"kept.json"});
  }
  ::chmod((dir / "read-only").c_str(), 0755);
}

TEST_CASE("write_new_file_atomically never writes over a file: the next free numbered name",
          "[unit][files]") {
  const Folder dir("new-names");
  const fs::path file = dir / "01-level-20240101-120000.json";
  std::string error;
  std::vector<fs::path> written;
  for (int i = 0; i < 3; ++i) {
    const auto out = tire::write_new_file_atomically(file, "save " + std::to_string(i), error);
    REQUIRE(out);
    written.push_back(*out);
  }
  CHECK(written[0] == file);
  CHECK(written[1] == dir / "01-level-20240101-120000-2.json");
  CHECK(written[2] == dir / "01-level-20240101-120000-3.json");
  for (int i = 0; i < 3; ++i)
    CHECK(contents_of(written[static_cast<std::size_t>(i)]) == "save " + std::to_string(i));
  // A name held by a symbolic link is taken too: nothing is written through it.
  const fs::path victim = dir / "victim";
  put(victim, "untouched");
  fs::create_symlink(victim, dir / "01-level-20240101-120000-4.json");
  const auto fifth = tire::write_new_file_atomically(file, "save 4", error);
  REQUIRE(fifth);
  CHECK(*fifth == dir / "01-level-20240101-120000-5.json");
  CHECK(contents_of(victim) == "untouched");
  // No extension: the number goes at the end.
  const auto a = tire::write_new_file_atomically(dir / "plain", "a", error);
  const auto b = tire::write_new_file_atomically(dir / "plain", "b", error);
  REQUIRE((a && b));
  CHECK(*b == dir / "plain-2");
  // A folder that does not exist: an error naming the file.
  CHECK_FALSE(tire::write_new_file_atomically(dir / "nowhere" / "x.json", "x", error));
  CHECK(error.find((dir / "nowhere" / "x.json").string()) != std::string::npos);
}

TEST_CASE("same_file follows symbolic and hard links", "[unit][files]") {
  const Folder dir("same");
  put(dir / "a", "a");
  put(dir / "b", "a");
  fs::create_symlink("a", dir / "link");
  fs::create_hard_link(dir / "a", dir / "hard");
  CHECK(tire::same_file(dir / "a", dir / "a"));
  CHECK(tire::same_file(dir / "link", dir / "a"));
  CHECK(tire::same_file(dir / "hard", dir / "link"));
  CHECK_FALSE(tire::same_file(dir / "a", dir / "b"));
  CHECK_FALSE(tire::same_file(dir / "a", dir / "missing"));
  CHECK_FALSE(tire::same_file(dir / "missing", dir / "missing"));
}

TEST_CASE("printable escapes what could end a message's line, and keeps the rest", "[unit][files]") {
  using tire::printable;
  CHECK(printable("levels/01-first-roll.json") == "levels/01-first-roll.json");
  CHECK(printable("x\nlevels/01.json: ok") == "x\\nlevels/01.json: ok");
  CHECK(printable("a\rb\tc") == "a\\rb\\tc");
  CHECK(printable(std::string("a\0b", 3)) == "a\\x00b");
  CHECK(printable("\x1b[2Jclear\x7f") == "\\x1b[2Jclear\\x7f");
  CHECK(printable("back\\slash") == "back\\\\slash");
  CHECK(printable("next\xc2\x85line") == "next\\u0085line");  // NEL, a line end to some readers
  CHECK(printable("caf\xc3\xa9 \xe2\x80\x94 ok") == "caf\xc3\xa9 \xe2\x80\x94 ok");  // UTF-8 kept
  CHECK(printable("") == "");
}

TEST_CASE("a failed write names its file with control characters escaped", "[unit][files]") {
  const Folder dir("printable");
  std::string error;
  CHECK_FALSE(write_file_atomically(dir / "missing\nfolder" / "out.json", "x", error));
  CHECK(error.find("missing\\nfolder") != std::string::npos);
  CHECK(error.find('\n') == std::string::npos);
}

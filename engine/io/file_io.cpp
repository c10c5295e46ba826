#include "tire/io/file_io.h"

#include <fcntl.h>
#ifdef TIRE_HAVE_OPENSSL
#include <openssl/evp.h>
#else
#include <nettle/sha2.h>
#endif
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>

namespace tire {

std::optional<std::string> read_file(const std::filesystem::path& file, std::uintmax_t max_bytes,
                                     std::string& error) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    error = std::filesystem::exists(file, ec) ? "not a regular file" : "no such file";
    return std::nullopt;
  }
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) {
    error = "cannot read: " + ec.message();
    return std::nullopt;
  }
  if (size > max_bytes) {
    error = "file is " + std::to_string(size) + " bytes; the limit is " + std::to_string(max_bytes);
    return std::nullopt;
  }
  // Straight into a string of the size the file has: one copy in memory, never more than the limit.
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    error = "cannot open the file";
    return std::nullopt;
  }
  std::string contents(static_cast<std::size_t>(size), '\0');
  in.read(contents.data(), static_cast<std::streamsize>(size));
  if (in.bad()) {
    error = "cannot read the file";
    return std::nullopt;
  }
  contents.resize(static_cast<std::size_t>(in.gcount()));  // it shrank while we read it
  char more[1 << 16];  // it grew while we read it: take the rest, up to the limit
  while (in && (in.read(more, sizeof more), in.gcount() > 0)) {
    contents.append(more, static_cast<std::size_t>(in.gcount()));
    if (contents.size() > max_bytes) {
      error = "file is larger than the limit of " + std::to_string(max_bytes) + " bytes";
      return std::nullopt;
    }
  }
  return contents;
}

namespace {

// How many symbolic links a target may go through (Linux's own limit, SYMLOOP_MAX, is 40).
constexpr int kMaxLinks = 40;
// Names tried for a temporary before giving up: each is 64 random bits, so a clash means someone
// creates names beside the file on purpose.
constexpr int kMaxTemporaryNames = 16;
// Names tried by write_new_file_atomically: <stem>, <stem>-2, ... <stem>-kMaxNewNames.
constexpr int kMaxNewNames = 1000;

std::string errno_text(int error) { return std::strerror(error); }

// What a file that is not a regular one is, for the error.
std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

// 64 random bits for a temporary's name: the kernel's (getentropy), else /dev/urandom's, else the
// clock's, the process's and a counter's. The name is created with O_EXCL, so even a guessed one
// costs a retry, never a file; randomness only keeps others from occupying the names in advance.
std::uint64_t random_bits() {
  std::uint64_t r = 0;
  if (::getentropy(&r, sizeof r) == 0) return r;
  if (const int fd = ::open("/dev/urandom", O_RDONLY | O_CLOEXEC); fd >= 0) {
    const ssize_t n = ::read(fd, &r, sizeof r);
    ::close(fd);
    if (n == static_cast<ssize_t>(sizeof r)) return r;
  }
  static std::atomic<std::uint64_t> counter{0};
  const auto ticks = static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
  return (ticks * 0x9e3779b97f4a7c15u) ^ (static_cast<std::uint64_t>(::getpid()) << 32) ^
         counter.fetch_add(1);
}

// Where the bytes for `file` go.
struct Target {
  std::filesystem::path path;  // `file`, or the file its symbolic links lead to
  bool exists = false;         // a regular file is there (else it is created)
  struct stat st {};           // its mode and owner, when it exists
};

// `file` with its symbolic links followed: a link is kept and the file it names is written (a
// dangling link's target is created). Refused: a directory, FIFO, device or socket (renaming over
// one would put a regular file in its place: `--record /dev/null` as root would replace
// /dev/null), and a loop of links.
std::optional<Target> resolve_target(const std::filesystem::path& file, std::string& error) {
  Target target{file};
  for (int links = 0;; ++links) {
    if (::lstat(target.path.c_str(), &target.st) != 0) {
      const int e = errno;
      if (e == ENOENT) return target;  // a new file (a missing folder is found on creating it)
      error = "cannot write " + printable(file.string()) + ": " + errno_text(e);
      return std::nullopt;
    }
    const std::string through =
        target.path == file ? "" : " (a symbolic link to " + printable(target.path.string()) + ")";
    if (S_ISLNK(target.st.st_mode)) {
      std::error_code ec;
      const std::filesystem::path to = std::filesystem::read_symlink(target.path, ec);
      if (ec || links == kMaxLinks) {
        error = "cannot write " + printable(file.string()) + through + ": " +
                (ec ? ec.message() : std::string("too many levels of symbolic links"));
        return std::nullopt;
      }
      // A relative link is relative to the folder it is in.
      target.path = to.is_absolute() ? to : target.path.parent_path() / to;
      continue;
    }
    if (!S_ISREG(target.st.st_mode)) {
      error = "cannot write " + printable(file.string()) + through + ": it is " + kind_of(target.st.st_mode) +
              ", not a regular file";
      return std::nullopt;
    }
    target.exists = true;
    return target;
  }
}

std::filesystem::path folder_of(const std::filesystem::path& file) {
  return file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
}

// Writes `contents` to a temporary file of its own beside `target`, flushed to disk, with the mode
// and owner of the file it will replace (a new file gets 0644, less the umask). Returns its name.
std::optional<std::filesystem::path> write_temporary(const Target& target, std::string_view contents,
                                                     std::string& error) {
  // O_EXCL|O_NOFOLLOW: a file or symbolic link already at the name is never opened or followed,
  // so nothing planted beside the target can redirect the write.
  static constexpr char hex[] = "0123456789abcdef";
  std::filesystem::path temp;
  int fd = -1;
  for (int attempt = 0; attempt < kMaxTemporaryNames && fd < 0; ++attempt) {
    std::string name = target.path.filename().string() + ".tmp-";
    for (std::uint64_t r = random_bits(), i = 0; i < 16; ++i, r >>= 4) name += hex[r & 15];
    temp = folder_of(target.path) / name;
    fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC,
                target.exists ? 0600 : 0644);
    if (fd < 0 && errno != EEXIST) break;
  }
  if (fd < 0) {
    const int e = errno;
    error = "cannot write " + printable(target.path.string()) + ": cannot create the temporary file " +
            printable(temp.string()) + ": " + errno_text(e);
    return std::nullopt;
  }
  const auto fail = [&](const std::string& what) {
    const int e = errno;
    error = "cannot write " + printable(target.path.string()) + ": cannot " + what + " the temporary file " +
            printable(temp.string()) + ": " + errno_text(e);
    ::close(fd);
    ::unlink(temp.c_str());
    return std::nullopt;
  };
  if (target.exists) {
    // The replaced file's owner (best effort: only root may give a file away) and then its mode
    // (after the owner, which clears set-user-ID bits; fchmod is not subject to the umask).
    if (target.st.st_uid != ::geteuid() || target.st.st_gid != ::getegid()) {
      if (::fchown(fd, target.st.st_uid, target.st.st_gid) != 0) {
        // not ours to give: the new file stays this user's
      }
    }
    if (::fchmod(fd, target.st.st_mode & 07777) != 0) return fail("set the mode of");
  }
  std::size_t written = 0;
  while (written < contents.size()) {
    const ssize_t n = ::write(fd, contents.data() + written, contents.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n == 0) errno = ENOSPC;
    if (n <= 0) return fail("write");
    written += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) return fail("flush");
  if (::close(fd) != 0) {
    const int e = errno;
    error = "cannot write " + printable(target.path.string()) + ": cannot flush the temporary file " +
            printable(temp.string()) + ": " + errno_text(e);
    ::unlink(temp.c_str());
    return std::nullopt;
  }
  return temp;
}

// The rename or link itself reaches the disk with the folder (best effort: a kill cannot undo it).
void sync_folder(const std::filesystem::path& file) {
  if (const int dfd = ::open(folder_of(file).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
}

// Gives the written temporary the name `file` only if no file has it. 0 when done, EEXIST when the
// name is taken (the temporary is removed either way), another errno on failure.
int link_new(const std::filesystem::path& temp, const std::filesystem::path& file) {
  // link(2) fails on an existing name, where rename(2) would replace it.
  if (::link(temp.c_str(), file.c_str()) == 0) {
    ::unlink(temp.c_str());
    return 0;
  }
  int result = errno;
  if (result != EEXIST) {
    // A file system without hard links: take the name with an empty file created O_EXCL, then
    // rename over it. Only here can a reader see the file empty for a moment.
    if (const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
        fd >= 0) {
      ::close(fd);
      if (::rename(temp.c_str(), file.c_str()) == 0) return 0;
      result = errno;
      ::unlink(file.c_str());
    } else {
      result = errno;
    }
  }
  ::unlink(temp.c_str());
  return result;
}

}  // namespace

std::string check_output_file(const std::filesystem::path& file) {
  std::string error;
  return resolve_target(file, error) ? "" : error;
}

bool same_file(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code ec;
  return std::filesystem::equivalent(a, b, ec) && !ec;
}

std::vector<std::filesystem::path> json_files(const std::filesystem::path& dir, std::string& error) {
  std::vector<std::filesystem::path> out;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().extension() == ".json" && it->is_regular_file(ec)) out.push_back(it->path());
  if (ec) error = printable(dir.string()) + ": " + ec.message();
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.filename() < b.filename(); });
  return out;
}

bool write_file_atomically(const std::filesystem::path& file, std::string_view contents, std::string& error) {
  const std::optional<Target> target = resolve_target(file, error);
  if (!target) return false;
  const std::optional<std::filesystem::path> temp = write_temporary(*target, contents, error);
  if (!temp) return false;
  if (::rename(temp->c_str(), target->path.c_str()) != 0) {
    const int e = errno;
    error = "cannot write " + printable(target->path.string()) +
            ": cannot rename the temporary file over it: " + errno_text(e);
    ::unlink(temp->c_str());
    return false;
  }
  sync_folder(target->path);
  return true;
}

std::optional<std::filesystem::path> write_new_file_atomically(const std::filesystem::path& file,
                                                               std::string_view contents,
                                                               std::string& error) {
  const std::string stem = file.stem().string(), extension = file.extension().string();
  for (int n = 1; n <= kMaxNewNames; ++n) {
    const std::filesystem::path name =
        n == 1 ? file : file.parent_path() / (stem + "-" + std::to_string(n) + extension);
    struct stat st {};
    if (::lstat(name.c_str(), &st) == 0) continue;  // taken (a link too: nothing is written through)
    if (const int e = errno; e != ENOENT) {
      error = "cannot write " + printable(name.string()) + ": " + errno_text(e);
      return std::nullopt;
    }
    const std::optional<std::filesystem::path> temp = write_temporary(Target{name}, contents, error);
    if (!temp) return std::nullopt;
    const int result = link_new(*temp, name);
    if (result == EEXIST) continue;  // another writer took the name since lstat
    if (result != 0) {
      error = "cannot write " + printable(name.string()) + ": " + errno_text(result);
      return std::nullopt;
    }
    sync_folder(name);
    return name;
  }
  error = "cannot write " + printable(file.string()) + ": it and the next " +
          std::to_string(kMaxNewNames - 1) + " numbered names (" + printable(stem + "-2" + extension) +
          ", ...) all exist";
  return std::nullopt;
}

std::string printable(std::string_view text) {
  static constexpr char hex[] = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    const auto next = i + 1 < text.size() ? static_cast<unsigned char>(text[i + 1]) : 0u;
    if (c == '\\') {
      out += "\\\\";
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c < 0x20 || c == 0x7f) {
      out += {'\\', 'x', hex[c >> 4], hex[c & 15]};
    } else if (c == 0xc2 && next >= 0x80 && next <= 0x9f) {  // U+0080..U+009F in UTF-8 (NEL among them)
      out += {'\\', 'u', '0', '0', hex[next >> 4], hex[next & 15]};
      ++i;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

bool is_lowercase_hex(std::string_view text, std::size_t digits) {
  return text.size() == digits && std::all_of(text.begin(), text.end(), [](char c) {
           return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
         });
}

std::string sha256_hex(std::string_view bytes) {
#ifdef TIRE_HAVE_OPENSSL
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  EVP_Digest(bytes.data(), bytes.size(), digest, &length, EVP_sha256(), nullptr);
#else  // Nettle, where there is no OpenSSL (the browser build)
  sha256_ctx context;
  sha256_init(&context);
  sha256_update(&context, bytes.size(), reinterpret_cast<const std::uint8_t*>(bytes.data()));
  std::uint8_t digest[SHA256_DIGEST_SIZE];
  sha256_digest(&context, SHA256_DIGEST_SIZE, digest);
  const unsigned int length = SHA256_DIGEST_SIZE;
#endif
  static constexpr char hex[] = "0123456789abcdef";
  std::string out;
  for (unsigned int i = 0; i < length; ++i) {
    out += hex[digest[i] >> 4];
    out += hex[digest[i] & 0xf];
  }
  return out;
}

}  // namespace tire

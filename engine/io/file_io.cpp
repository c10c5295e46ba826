#include "tire/io/file_io.h"

#include <fcntl.h>
#ifdef TIRE_HAVE_OPENSSL
#include <openssl/evp.h>
#else
#include <nettle/sha2.h>
#endif
#include <unistd.h>

#include <atomic>
#include <cerrno>
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

bool write_file_atomically(const std::filesystem::path& file, std::string_view contents, std::string& error) {
  // Unique per process and per call, so that two writers of the same file never share a temporary.
  static std::atomic<unsigned> serial{0};
  const std::filesystem::path temp =
      file.string() + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(serial.fetch_add(1));
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    error = "cannot create " + temp.string() + ": " + std::strerror(errno);
    return false;
  }
  std::size_t written = 0;
  while (written < contents.size()) {
    const ssize_t n = ::write(fd, contents.data() + written, contents.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      error = "cannot write " + temp.string() + ": " + std::strerror(errno);
      ::close(fd);
      ::unlink(temp.c_str());
      return false;
    }
    written += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    error = "cannot flush " + temp.string() + ": " + std::strerror(errno);
    ::unlink(temp.c_str());
    return false;
  }
  if (::rename(temp.c_str(), file.c_str()) != 0) {
    error = "cannot replace " + file.string() + ": " + std::strerror(errno);
    ::unlink(temp.c_str());
    return false;
  }
  // The rename itself reaches the disk with the directory (best effort: a kill cannot undo it anyway).
  const std::filesystem::path dir = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  if (const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
  return true;
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

// Files in and out: bounded reads of untrusted files, atomic writes (nothing half-written is ever
// left where a reader could find it), and content digests.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace tire {

// The whole file, or nullopt with `error` set ("no such file", "file is N bytes; the limit is M").
std::optional<std::string> read_file(const std::filesystem::path& file, std::uintmax_t max_bytes,
                                     std::string& error);

// Writes `contents` to a temporary file beside `file`, flushes it to disk, then renames it over
// `file`: a crash or kill at any moment leaves either the old file or the new one, whole.
bool write_file_atomically(const std::filesystem::path& file, std::string_view contents, std::string& error);

// SHA-256 of the bytes, as 64 lowercase hex digits (OpenSSL's; Nettle's where it is built without
// OpenSSL, as in the browser).
std::string sha256_hex(std::string_view bytes);

}  // namespace tire

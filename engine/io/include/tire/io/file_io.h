// Files in and out: bounded reads of untrusted files, atomic writes (nothing half-written is ever
// left where a reader could find it), and content digests.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tire {

// The whole file, or nullopt with `error` set ("no such file", "file is N bytes; the limit is M").
std::optional<std::string> read_file(const std::filesystem::path& file, std::uintmax_t max_bytes,
                                     std::string& error);

// Writes `contents` to a temporary file beside `file`, flushes it to disk, then renames it over
// `file`: a crash or kill at any moment leaves either the old file or the new one, whole. False with
// `error` set (naming the file and what is wrong) when it cannot.
// - The temporary has a random name and is created with O_EXCL|O_NOFOLLOW: nothing already beside
//   the file (a symbolic link planted at a guessed name) is opened or followed.
// - `file` must be a regular file or not exist: a directory, FIFO, device or socket is refused,
//   never replaced by a regular file.
// - A symbolic link is written through: the file it leads to gets the contents, the link stays.
// - An existing file keeps its mode (and its owner, where the writer may set it); a new one gets
//   0644 less the umask.
bool write_file_atomically(const std::filesystem::path& file, std::string_view contents, std::string& error);

// As write_file_atomically, but never over an existing file: `file` when nothing has that name
// (a symbolic link counts), else the first free one of <stem>-2<ext>, <stem>-3<ext>, ... The name
// is taken with link(2), which fails when it exists, so two writers at once get two files. Returns
// the file written, or nullopt with `error` set.
std::optional<std::filesystem::path> write_new_file_atomically(const std::filesystem::path& file,
                                                               std::string_view contents, std::string& error);

// "" when write_file_atomically(file, ...) would not refuse `file` for what it is (a directory,
// FIFO, device, socket, a loop of links), else the error it would give: for refusing an output
// before the work that makes it.
std::string check_output_file(const std::filesystem::path& file);

// True when `a` and `b` are the same existing file (symbolic and hard links followed); false when
// either does not exist.
bool same_file(const std::filesystem::path& a, const std::filesystem::path& b);

// The *.json regular files of folder `dir`, sorted by file name; `error` says why the folder could
// not be read (what was read before the failure is returned).
std::vector<std::filesystem::path> json_files(const std::filesystem::path& dir, std::string& error);

// `text` (a path, a key, anything a user or a file chose) as it may appear inside a one-line
// message: a newline, carriage return or tab is written \n, \r, \t, any other control character
// (C0, DEL, C1) \xHH or \u00HH, and a backslash \\, so that no name can end a message's line and
// forge another ("x\nlevels/01.json: ok"). Anything else, UTF-8 included, is kept as it is.
std::string printable(std::string_view text);

// SHA-256 of the bytes, as 64 lowercase hex digits (OpenSSL's; Nettle's where it is built without
// OpenSSL, as in the browser).
std::string sha256_hex(std::string_view bytes);

// Whether `text` is `digits` lowercase hex digits, as sha256_hex (64) and the state hash (16) write.
bool is_lowercase_hex(std::string_view text, std::size_t digits);

}  // namespace tire

// SHA-256 (FIPS 180-4) without OpenSSL: for builds that have no libcrypto (the browser build,
// README "In a browser"). Private to the io layer; sha256_hex (tire/io/file_io.h) uses it there,
// OpenSSL's otherwise, and a unit test checks that both agree.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

namespace tire::detail {

std::array<std::uint8_t, 32> sha256_portable(std::string_view bytes);

}  // namespace tire::detail

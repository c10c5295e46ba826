# The browser build's dependencies (included by the top level when EMSCRIPTEN): tools/web builds
# SDL2 and Box2D from Debian's source packages into TIRE_WEB_PREFIX, links the header-only
# libraries' folders (nlohmann/, CLI/) into its include/, and passes Dear ImGui's unpacked source
# package as TIRE_IMGUI_SOURCE_DIR. CMAKE_FIND_ROOT_PATH names the prefix, so that find_package
# finds these builds before the emscripten sysroot's stand-in SDL2 package (-sUSE_SDL=2, which
# would download a port).
set(TIRE_WEB_PREFIX "" CACHE PATH "Where tools/web installed SDL2 and Box2D built for the browser")
set(TIRE_IMGUI_SOURCE_DIR "" CACHE PATH "Dear ImGui's unpacked source package (apt-get source imgui)")
if(NOT TIRE_WEB_PREFIX OR NOT TIRE_IMGUI_SOURCE_DIR)
  message(FATAL_ERROR "The browser build is configured by ./tools/web (TIRE_WEB_PREFIX, TIRE_IMGUI_SOURCE_DIR)")
endif()

# One thread, no SharedArrayBuffer: never -pthread. Exceptions are caught (a level that does not
# parse is an error message, not an abort).
add_compile_options(-fexceptions)
add_link_options(-fexceptions)

find_package(box2d 2.4 REQUIRED CONFIG)
find_package(SDL2 REQUIRED CONFIG)
if(NOT SDL2_DIR MATCHES "^${TIRE_WEB_PREFIX}")
  message(FATAL_ERROR "SDL2 was found in ${SDL2_DIR}, not in ${TIRE_WEB_PREFIX}")
endif()

# Header-only: each library's own folder, never the host's /usr/include.
find_path(TIRE_WEB_NLOHMANN_INCLUDE nlohmann/json.hpp PATHS ${TIRE_WEB_PREFIX}/include NO_DEFAULT_PATH REQUIRED)
find_path(TIRE_WEB_CLI11_INCLUDE CLI/CLI.hpp PATHS ${TIRE_WEB_PREFIX}/include NO_DEFAULT_PATH REQUIRED)
add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED GLOBAL)
target_include_directories(nlohmann_json::nlohmann_json SYSTEM INTERFACE ${TIRE_WEB_NLOHMANN_INCLUDE})
add_library(CLI11::CLI11 INTERFACE IMPORTED GLOBAL)
target_include_directories(CLI11::CLI11 SYSTEM INTERFACE ${TIRE_WEB_CLI11_INCLUDE})

# Threads::Threads for the worker pool's headers; without -pthread it links nothing, and the pool
# runs every job on the calling thread (it cannot start threads there).
add_library(Threads::Threads INTERFACE IMPORTED GLOBAL)

# SHA-256 of level files: Nettle's (built by tools/web from Debian's source package) instead of
# OpenSSL's libcrypto.
set(TIRE_OPENSSL OFF)
find_library(TIRE_WEB_NETTLE nettle PATHS ${TIRE_WEB_PREFIX}/lib NO_DEFAULT_PATH REQUIRED)
find_path(TIRE_WEB_NETTLE_INCLUDE nettle/sha2.h PATHS ${TIRE_WEB_PREFIX}/include NO_DEFAULT_PATH REQUIRED)
add_library(nettle::nettle STATIC IMPORTED GLOBAL)
set_target_properties(nettle::nettle PROPERTIES IMPORTED_LOCATION ${TIRE_WEB_NETTLE})
target_include_directories(nettle::nettle SYSTEM INTERFACE ${TIRE_WEB_NETTLE_INCLUDE})

#!/usr/bin/env bash
# The web test (ctest -L web, docs/web.md): builds the game for the browser with
# ./tools/web --build-only, serves build-web/ on a free loopback port, and in headless Chromium
# (puppeteer-core) checks that the page draws the game, that real keys and clicks reach it, that
# ?frames=300&press=right:0-299 ends with the native game's player position to the last bit, that
# a best time and its ghost outlast a reload (IndexedDB), and that every shipped replay passes in
# the page.
#   tests/web/web_test.sh NATIVE_TIRE_GAME [OUTPUT_DIR]
# Exit 77 (skipped) where emscripten, Chromium or node is not installed.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
game=${1:?usage: web_test.sh NATIVE_TIRE_GAME [OUTPUT_DIR]}
out=${2:-$root/build-web/web-test}
mkdir -p "$out"

missing=()
command -v emcc >/dev/null || missing+=(emscripten)
command -v chromium >/dev/null || missing+=(chromium)
command -v node >/dev/null || missing+=(node)
if [ ${#missing[@]} -gt 0 ]; then
  printf -v list '%s, ' "${missing[@]}"
  echo "SKIPPED: web test: ${list%, } not installed (./tools/web installs emscripten and" \
    "chromium; CI's package list leaves them out)"
  exit 77
fi

echo "web test: building with ./tools/web --build-only (cached builds take seconds; a cold one ~15 min)"
started=$SECONDS
if ! "$root/tools/web" --build-only >"$out/build.log" 2>&1; then
  tail -n 40 "$out/build.log"
  echo "web test: ./tools/web --build-only failed (log: $out/build.log)"
  exit 1
fi
echo "web test: build done in $((SECONDS - started)) s"

# The native reference: the same level, frames and keys, offscreen.
native_args=(--frames 300 --press right:0-299)
SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy "$game" "$root/levels/01-first-roll.json" "${native_args[@]}" \
  >"$out/native.txt"
tail -n 1 "$out/native.txt" >"$out/native-300.json"
SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy "$game" "$root/levels/01-first-roll.json" --frames 400 \
  >"$out/native-idle.txt"
tail -n 1 "$out/native-idle.txt" >"$out/native-idle-400.json"

# A free loopback port, and the server stopped by its PID whatever happens.
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server "$port" --bind 127.0.0.1 --directory "$root/build-web" >"$out/server.log" 2>&1 &
server=$!
trap 'kill "$server" 2>/dev/null || true; wait "$server" 2>/dev/null || true' EXIT
for _ in $(seq 1 50); do
  python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$port/index.html')" 2>/dev/null && break
  sleep 0.2
done

replays=()
for f in "$root"/tests/replays/*.json; do replays+=("tests/replays/$(basename "$f")"); done
node "$root/tests/web/check_page.js" --url "http://127.0.0.1:$port/index.html" \
  --modules "$root/build-web/node_modules" --native "$out/native-300.json" \
  --native-idle "$out/native-idle-400.json" --out "$out" "${replays[@]}"

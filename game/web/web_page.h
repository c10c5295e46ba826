// What the browser build of tire-game does with its page (docs/web.md); compiled only
// there (emscripten).
#pragma once

#include <SDL.h>

#include <string>

namespace game::web {

// Gives the window the size the page's style gives the canvas (the whole browser window), so that
// the game fills the page and follows its size.
void follow_canvas_size(SDL_Window* window);

// Writes the exit summary (or a replay's result) into the page's element #summary, with the exit
// code in its data-exit attribute: what automation waits for. An empty line becomes {"exit": CODE}.
void publish_summary(const std::string& json, int exit_code);

// The data folder (progress.json, ghosts/) is the page's IndexedDB, mounted by web/persist.pre.js
// and read from it before main starts. Copies what the game wrote there since into IndexedDB, in the
// background; the page's #summary element gets data-persisted="N" once the N-th copy is stored.
void persist_data();

}  // namespace game::web

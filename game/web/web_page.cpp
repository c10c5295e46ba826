#include "web_page.h"

#include <emscripten.h>
#include <emscripten/html5.h>

namespace {

// clang-format off
EM_JS(void, tire_web_publish, (const char* text, int code), {
  const element = document.getElementById('summary');
  if (!element) return;
  element.textContent = UTF8ToString(text);
  element.dataset.exit = String(code);
});

EM_JS(void, tire_web_persist, (), {
  tirePersistData();  // web/persist.pre.js
});
// clang-format on

}  // namespace

namespace game::web {

void follow_canvas_size(SDL_Window* window) {
  if (!window) return;
  double css_w = 0.0, css_h = 0.0;
  if (emscripten_get_element_css_size("#canvas", &css_w, &css_h) != EMSCRIPTEN_RESULT_SUCCESS) return;
  const int w = static_cast<int>(css_w), h = static_cast<int>(css_h);
  int now_w = 0, now_h = 0;
  SDL_GetWindowSize(window, &now_w, &now_h);
  if (w > 0 && h > 0 && (w != now_w || h != now_h)) SDL_SetWindowSize(window, w, h);
}

void persist_data() { tire_web_persist(); }

void publish_summary(const std::string& json, int exit_code) {
  const std::string text = json.empty() ? "{\"exit\": " + std::to_string(exit_code) + "}" : json;
  tire_web_publish(text.c_str(), exit_code);
}

}  // namespace game::web

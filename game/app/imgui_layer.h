// Dear ImGui on an SDL window: Debian's libimgui ships the SDL2 platform backend compiled in
// (imgui_impl_sdl) but not the SDL_Renderer one, so this file draws ImGui's triangles itself with
// SDL_RenderGeometryRaw (the same few calls imgui_impl_sdlrenderer makes). All of the game's text
// goes through here.
#pragma once

#include <SDL.h>

struct ImFont;

namespace game {

class ImGuiLayer {
 public:
  ImGuiLayer() = default;
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;
  ~ImGuiLayer();

  bool init(SDL_Window* window, SDL_Renderer* renderer);
  // Feeds an input event to ImGui; true when ImGui wants it (the game should then ignore it).
  bool process_event(const SDL_Event& event);
  void new_frame();
  // Ends the frame and draws it on the renderer.
  void render();

  bool wants_mouse() const;
  bool wants_keyboard() const;
  ImFont* big_font() const { return big_; }

 private:
  bool create_font_texture();

  SDL_Renderer* renderer_ = nullptr;
  SDL_Texture* font_texture_ = nullptr;
  ImFont* big_ = nullptr;
  bool initialized_ = false;
};

}  // namespace game

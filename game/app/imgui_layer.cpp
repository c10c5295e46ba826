#include "app/imgui_layer.h"

#include <backends/imgui_impl_sdl.h>
#include <imgui.h>

#include <cstddef>
#include <filesystem>

namespace game {

namespace {

// A TrueType font when the system has one (fonts-dejavu-core is on most Debian systems); ImGui's
// built-in bitmap font otherwise.
constexpr const char* kFontFiles[] = {
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/TTF/DejaVuSans.ttf",
};
constexpr const char* kBoldFontFiles[] = {
    "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf",
    "/usr/share/fonts/TTF/DejaVuSans-Bold.ttf",
};

// What the interface writes beyond ASCII, from the level reference's tables and the parameter
// table: Latin-1 (° ± ² ³ · ×), Greek (α Δ μ τ), punctuation (– …), superscripts and subscripts
// (the ⁶ of "10⁶", μ₁), arrows (→) and mathematical operators (− √ ≈). DejaVu Sans has them all;
// ImGui's default ranges stop at Latin-1 and drew "?" for the rest (tooltips read "(0, 10?]").
constexpr ImWchar kGlyphRanges[] = {
    0x0020, 0x00FF,  // Basic Latin, Latin-1 Supplement
    0x0370, 0x03FF,  // Greek
    0x2010, 0x205E,  // General Punctuation
    0x2070, 0x209F,  // Superscripts and Subscripts
    0x2190, 0x21FF,  // Arrows
    0x2200, 0x22FF,  // Mathematical Operators
    0,
};

const char* first_existing(const auto& files) {
  std::error_code ec;
  for (const char* f : files)
    if (std::filesystem::exists(f, ec)) return f;
  return nullptr;
}

}  // namespace

ImGuiLayer::~ImGuiLayer() {
  if (!initialized_) return;
  if (font_texture_) SDL_DestroyTexture(font_texture_);
  ImGui_ImplSDL2_Shutdown();
  ImGui::DestroyContext();
}

bool ImGuiLayer::init(SDL_Window* window, SDL_Renderer* renderer) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  initialized_ = true;
  renderer_ = renderer;
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini in the working directory
  io.BackendRendererName = "tire-game SDL_Renderer";
  io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;

  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 6.0f;
  style.FrameRounding = 4.0f;
  style.Colors[ImGuiCol_WindowBg].w = 0.88f;

  if (const char* file = first_existing(kFontFiles)) {
    io.Fonts->AddFontFromFileTTF(file, 17.0f, nullptr, kGlyphRanges);
    const char* bold = first_existing(kBoldFontFiles);
    big_ = io.Fonts->AddFontFromFileTTF(bold ? bold : file, 34.0f, nullptr, kGlyphRanges);
  } else {
    ImFontConfig config;
    config.SizePixels = 15.0f;
    io.Fonts->AddFontDefault(&config);
    config.SizePixels = 30.0f;
    big_ = io.Fonts->AddFontDefault(&config);
  }
  if (!ImGui_ImplSDL2_InitForSDLRenderer(window)) return false;
  return create_font_texture();
}

bool ImGuiLayer::create_font_texture() {
  ImGuiIO& io = ImGui::GetIO();
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  font_texture_ =
      SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_RGBA32, SDL_TEXTUREACCESS_STATIC, width, height);
  if (!font_texture_) return false;
  SDL_UpdateTexture(font_texture_, nullptr, pixels, 4 * width);
  SDL_SetTextureBlendMode(font_texture_, SDL_BLENDMODE_BLEND);
  io.Fonts->SetTexID(font_texture_);
  return true;
}

bool ImGuiLayer::process_event(const SDL_Event& event) {
  ImGui_ImplSDL2_ProcessEvent(&event);
  switch (event.type) {
    case SDL_MOUSEBUTTONDOWN:
    case SDL_MOUSEBUTTONUP:
    case SDL_MOUSEWHEEL:
    case SDL_MOUSEMOTION: return wants_mouse();
    case SDL_KEYDOWN:
    case SDL_KEYUP:
    case SDL_TEXTINPUT: return wants_keyboard();
    default: return false;
  }
}

void ImGuiLayer::new_frame() {
  ImGui_ImplSDL2_NewFrame();
  // Two frames can share a timestamp where the clock is coarse (a browser's): ImGui asserts that
  // time passes.
  ImGuiIO& io = ImGui::GetIO();
  if (!(io.DeltaTime > 0.0f)) io.DeltaTime = 1.0e-4f;
  ImGui::NewFrame();
}

bool ImGuiLayer::wants_mouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool ImGuiLayer::wants_keyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

void ImGuiLayer::render() {
  ImGui::Render();
  const ImDrawData* data = ImGui::GetDrawData();
  if (!data || data->DisplaySize.x <= 0.0f || data->DisplaySize.y <= 0.0f) return;
  // The renderer's output may be larger than the window (high-DPI): scale ImGui's coordinates.
  int out_w = 0, out_h = 0;
  SDL_GetRendererOutputSize(renderer_, &out_w, &out_h);
  const float sx = static_cast<float>(out_w) / data->DisplaySize.x;
  const float sy = static_cast<float>(out_h) / data->DisplaySize.y;
  float old_sx = 1.0f, old_sy = 1.0f;
  SDL_RenderGetScale(renderer_, &old_sx, &old_sy);
  SDL_RenderSetScale(renderer_, sx, sy);
  SDL_RenderSetViewport(renderer_, nullptr);

  const ImVec2 off = data->DisplayPos;
  for (int n = 0; n < data->CmdListsCount; ++n) {
    const ImDrawList* list = data->CmdLists[n];
    const ImDrawVert* vertices = list->VtxBuffer.Data;
    const ImDrawIdx* indices = list->IdxBuffer.Data;
    for (const ImDrawCmd& cmd : list->CmdBuffer) {
      if (cmd.UserCallback) {
        if (cmd.UserCallback != ImDrawCallback_ResetRenderState) cmd.UserCallback(list, &cmd);
        continue;
      }
      const float x0 = cmd.ClipRect.x - off.x, y0 = cmd.ClipRect.y - off.y;
      const float x1 = cmd.ClipRect.z - off.x, y1 = cmd.ClipRect.w - off.y;
      if (x1 <= x0 || y1 <= y0) continue;
      const SDL_Rect clip{static_cast<int>(x0), static_cast<int>(y0), static_cast<int>(x1 - x0),
                          static_cast<int>(y1 - y0)};
      SDL_RenderSetClipRect(renderer_, &clip);
      const char* base = reinterpret_cast<const char*>(vertices + cmd.VtxOffset);
      const auto* xy = reinterpret_cast<const float*>(base + offsetof(ImDrawVert, pos));
      const auto* uv = reinterpret_cast<const float*>(base + offsetof(ImDrawVert, uv));
      const auto* color = reinterpret_cast<const SDL_Color*>(base + offsetof(ImDrawVert, col));
      SDL_RenderGeometryRaw(renderer_, static_cast<SDL_Texture*>(cmd.GetTexID()), xy, sizeof(ImDrawVert),
                            color, sizeof(ImDrawVert), uv, sizeof(ImDrawVert),
                            list->VtxBuffer.Size - static_cast<int>(cmd.VtxOffset), indices + cmd.IdxOffset,
                            static_cast<int>(cmd.ElemCount), sizeof(ImDrawIdx));
    }
  }
  SDL_RenderSetClipRect(renderer_, nullptr);
  SDL_RenderSetScale(renderer_, old_sx, old_sy);
}

}  // namespace game

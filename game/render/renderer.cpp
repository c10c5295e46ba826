#include "render/renderer.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

#include "render/debug_draw_sdl.h"
#include "render/vehicle_draw.h"

namespace game {

namespace {

constexpr SDL_Color kSkyTop = rgba(104, 158, 214);
constexpr SDL_Color kSkyBottom = rgba(206, 228, 243);
constexpr SDL_Color kGridMinor = rgba(255, 255, 255, 34);
constexpr SDL_Color kGridMajor = rgba(255, 255, 255, 70);
constexpr SDL_Color kEarth = rgba(122, 92, 62);
constexpr SDL_Color kEarthEdge = rgba(74, 54, 36);
constexpr SDL_Color kBedrock = rgba(66, 52, 42);
// The deep under the level, seen down a pit or past a ledge: the sky fades to it over kDeepFade.
constexpr SDL_Color kDeep = rgba(18, 20, 30);
constexpr double kDeepFade = 4.0;  // m
constexpr SDL_Color kGrass = rgba(96, 160, 64);
constexpr SDL_Color kStatic = rgba(104, 116, 134);
constexpr SDL_Color kDynamic = rgba(214, 146, 66);
constexpr SDL_Color kKinematic = rgba(64, 170, 176);
constexpr SDL_Color kSidewall = rgba(38, 38, 42);
constexpr SDL_Color kTreadDark = rgba(22, 22, 24);
constexpr SDL_Color kTreadLight = rgba(78, 78, 84);
constexpr SDL_Color kRimPlayer = rgba(240, 176, 48);
constexpr SDL_Color kRimOther = rgba(176, 182, 194);
constexpr SDL_Color kHubCap = rgba(60, 60, 66);

SDL_Color prop_color(const tire::PropView& p) {
  switch (p.type) {
    case tire::PropType::dynamic_body: return kDynamic;
    case tire::PropType::kinematic_body: return kKinematic;
    case tire::PropType::static_body: break;
  }
  return kStatic;
}

ScreenPoint lerp(ScreenPoint a, ScreenPoint b, float t) {
  return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
}

SDL_Color mix(SDL_Color a, SDL_Color b, float t) {
  const auto m = [t](Uint8 x, Uint8 y) { return static_cast<int>(std::lround(x + (y - x) * t)); };
  return rgba(m(a.r, b.r), m(a.g, b.g), m(a.b, b.b), m(a.a, b.a));
}

}  // namespace

SDL_Color tire_texel(double x, double y, const TireLook& look) {
  // Everything in units of the outer radius, centred on the hub; y down, as on screen.
  const double r = std::sqrt(x * x + y * y);
  const double rho = look.inner_ratio;
  const double px = 1.0 / std::max(look.radius_pixels, 1.0);  // one screen pixel
  if (r < std::max(2.0 * px, 0.3 * rho)) return kHubCap;
  if (r < rho) {
    const double spoke = 0.5 * std::max(2.0 * px, 0.12 * rho);
    if (std::min(std::abs(x), std::abs(y)) < spoke) return darker(look.rim, 0.7f);
    if (r > rho - 1.5 * px) return darker(look.rim, 0.55f);
    return look.rim;
  }
  const double band = 1.0 - 0.42 * (1.0 - rho);
  if (r < band) return kSidewall;
  const double turn = std::atan2(y, x) / (2.0 * std::numbers::pi) + 0.5;  // [0, 1]
  const int block = static_cast<int>(turn * look.tread_blocks) % std::max(look.tread_blocks, 1);
  return block % 2 ? kTreadLight : kTreadDark;
}

void tire_image(const TireLook& look, int size, std::vector<std::uint32_t>& rgba_pixels) {
  // 4 × 4 samples a texel. The tire's outer ring is one texel inside the image's edge and what is
  // outside it has the tread's colours, so that filtering at the edge never mixes in a background.
  constexpr int kSamples = 4;
  rgba_pixels.assign(static_cast<std::size_t>(size) * size, 0);
  const double radius = 0.5 * size - 1.0;
  for (int ty = 0; ty < size; ++ty)
    for (int tx = 0; tx < size; ++tx) {
      int sum[4] = {0, 0, 0, 0};
      for (int sy = 0; sy < kSamples; ++sy)
        for (int sx = 0; sx < kSamples; ++sx) {
          const double x = (tx + (sx + 0.5) / kSamples - 0.5 * size) / radius;
          const double y = (ty + (sy + 0.5) / kSamples - 0.5 * size) / radius;
          const double r = std::sqrt(x * x + y * y);
          const double k = r > 0.999 ? 0.999 / r : 1.0;
          const SDL_Color c = tire_texel(x * k, y * k, look);
          sum[0] += c.r, sum[1] += c.g, sum[2] += c.b, sum[3] += c.a;
        }
      std::uint8_t bytes[4];
      for (int i = 0; i < 4; ++i)
        bytes[i] = static_cast<std::uint8_t>((sum[i] + kSamples * kSamples / 2) / (kSamples * kSamples));
      std::uint32_t packed = 0;
      std::memcpy(&packed, bytes, 4);  // SDL_PIXELFORMAT_RGBA32: bytes R, G, B, A in memory
      rgba_pixels[static_cast<std::size_t>(ty) * size + tx] = packed;
    }
}

WorldRenderer::~WorldRenderer() { release(); }

void WorldRenderer::release() {
  for (TireTexture& t : tire_textures_)
    if (t.texture) SDL_DestroyTexture(t.texture);
  tire_textures_.clear();
}

WorldRenderer::TireTexture* WorldRenderer::tire_texture(SDL_Renderer* renderer, const tire::TireView& t,
                                                        float radius_px, bool is_player) {
  if (!renderer) return nullptr;
  int size = 16;
  while (size < 128 && static_cast<float>(size) < 2.0f * radius_px) size *= 2;
  const int ratio = static_cast<int>(std::lround(t.inner_radius / t.outer_radius * 50.0));
  for (TireTexture& e : tire_textures_)
    if (e.size == size && e.ratio == ratio && e.player == is_player) return e.texture ? &e : nullptr;
  // First use of this look at this size: made once, kept until the renderer goes.
  TireTexture entry{size, ratio, is_player, nullptr, {}};
  TireLook look;
  look.inner_ratio = ratio / 50.0;
  look.radius_pixels = 0.5 * size;
  look.rim = is_player ? kRimPlayer : kRimOther;
  std::vector<std::uint32_t> pixels;
  tire_image(look, size, pixels);
  entry.texture = SDL_CreateTexture(renderer, SDL_PIXELFORMAT_RGBA32, SDL_TEXTUREACCESS_STATIC, size, size);
  if (entry.texture) {
    SDL_UpdateTexture(entry.texture, nullptr, pixels.data(), 4 * size);
    SDL_SetTextureBlendMode(entry.texture, SDL_BLENDMODE_NONE);  // opaque
    SDL_SetTextureScaleMode(entry.texture, SDL_ScaleModeLinear);
  }
  tire_textures_.push_back(std::move(entry));
  return tire_textures_.back().texture ? &tire_textures_.back() : nullptr;
}

void WorldRenderer::draw(Draw& d, const Camera& camera, const GameSession& session, double alpha,
                         const DebugOptions& debug) {
  const tire::Simulation& simulation = session.simulation();
  draw_background(d, camera);
  draw_goal(d, camera, simulation);
  draw_obstacles(d, camera, simulation);
  draw_props(d, camera, session, alpha);
  const std::optional<tire::TireId> player_id = simulation.player();
  const std::optional<tire::TireView> player = player_id ? simulation.tire(*player_id) : std::nullopt;
  // The tires are opaque: a batch of their own is drawn without blending. Small ones go into one
  // textured batch per look, drawn first.
  d.flush();
  // The debug view shades sleeping tires.
  const auto shaded = [&debug](const tire::TireView& t) { return debug.enabled && t.asleep; };
  for (std::size_t i = 0; const std::optional<tire::TireView> t = simulation.tire_at(i); ++i)
    if (!t->player) draw_tire(d, camera, session, *t, alpha, false, shaded(*t));
  for (TireTexture& tex : tire_textures_) {
    if (tex.vertices.empty()) continue;
    SDL_RenderGeometry(d.renderer(), tex.texture, tex.vertices.data(), static_cast<int>(tex.vertices.size()),
                       nullptr, 0);
    tex.vertices.clear();
  }
  if (player) draw_tire(d, camera, session, *player, alpha, true, shaded(*player));
  draw_heads(d, camera, session, alpha);
  if (debug.enabled) draw_debug(d, camera, session, alpha, debug);
  draw_grab(d, camera, session, alpha);
  d.flush();
}

void WorldRenderer::draw_background(Draw& d, const Camera& camera) {
  d.vertical_gradient(camera.width(), camera.height(), kSkyTop, kSkyBottom);
  // A metre grid, so that motion shows against the sky.
  const tire::Aabb view = camera.view();
  for (double x = std::floor(view.min.x); x <= view.max.x; x += 1.0) {
    const bool major = std::fmod(std::abs(x), 5.0) < 0.5;
    const float sx = camera.to_screen({x, 0}).x;
    d.line({sx, 0}, {sx, static_cast<float>(camera.height())}, major ? 1.5f : 1.0f,
           major ? kGridMajor : kGridMinor);
  }
  for (double y = std::floor(view.min.y); y <= view.max.y; y += 1.0) {
    const bool major = std::fmod(std::abs(y), 5.0) < 0.5;
    const float sy = camera.to_screen({0, y}).y;
    d.line({0, sy}, {static_cast<float>(camera.width()), sy}, major ? 1.5f : 1.0f,
           major ? kGridMajor : kGridMinor);
  }
  // Below the ground's bottom is the deep, seen down a pit or past the level's edge: the sky fades
  // to dark there. The ground itself goes on down as rock, under each piece of it only
  // (draw_obstacles, draw_props), so that a chasm stays open to the bottom of the screen.
  if (floor_ > view.min.y) {
    const auto w = static_cast<float>(camera.width()), h = static_cast<float>(camera.height());
    const float floor = camera.to_screen({0, floor_}).y, deep = camera.to_screen({0, floor_ - kDeepFade}).y;
    const SDL_Color sky = mix(kSkyTop, kSkyBottom, std::clamp(floor / h, 0.0f, 1.0f));
    const auto shade = [&](float y) {
      return mix(sky, kDeep, std::clamp((y - floor) / (deep - floor), 0.0f, 1.0f));
    };
    const float top = std::max(floor, 0.0f), end = std::min(deep, h);
    if (end > top) d.vertical_gradient({0, top}, {w, end}, shade(top), shade(end));
    if (deep < h) d.rect({0, std::max(deep, 0.0f)}, {w, h}, kDeep);
  }
}

void WorldRenderer::draw_obstacles(Draw& d, const Camera& camera, const tire::Simulation& simulation) {
  const tire::Aabb view = camera.view();
  const float grass = std::max(3.0f, camera.pixels(0.08));
  for (const tire::Obstacle& o : simulation.obstacles()) {
    // An obstacle that stands on the ground (its bottom below the ground's surface): rock goes on
    // under it to the bottom of the view. A platform floats.
    if (o.box.min.y < surface_ && o.box.min.y > view.min.y && o.box.min.x < view.max.x &&
        o.box.max.x > view.min.x)
      d.rect(camera.to_screen(o.box.min), camera.to_screen({o.box.max.x, view.min.y}), kBedrock);
    if (!o.box.overlaps(view)) continue;
    const ScreenPoint a = camera.to_screen(o.box.min), b = camera.to_screen(o.box.max);
    d.rect(a, b, kEarth);
    d.rect_outline(a, b, 1.5f, kEarthEdge);
    d.rect({a.x, b.y}, {b.x, std::min(a.y, b.y + grass)}, kGrass);
  }
}

void WorldRenderer::draw_props(Draw& d, const Camera& camera, const GameSession& session, double alpha) {
  const tire::Simulation& simulation = session.simulation();
  for (tire::PropId i = 0; i < simulation.prop_count(); ++i) {
    const std::optional<tire::PropView> view = simulation.prop(i);
    if (!view || !view->alive) continue;
    const tire::PropView& g = *view;
    const tire::Pose pose = session.interpolated_pose(i, alpha);
    const SDL_Color fill = prop_color(g);
    const SDL_Color edge = darker(fill);
    shape_.clear();
    for (const tire::Vec2& v : g.vertices) shape_.push_back(camera.to_screen(pose.to_world(v)));
    switch (g.shape) {
      case tire::PropShape::box:
      case tire::PropShape::polygon:
        d.convex(shape_, fill);
        d.polyline(shape_, true, 2.0f, edge);
        break;
      case tire::PropShape::circle: {
        const ScreenPoint c = camera.to_screen(pose.position);
        const float r = camera.pixels(g.radius);
        d.circle(c, r, edge, 32);
        d.circle(c, std::max(1.0f, r - 2.0f), fill, 32);
        // A radius, so that rolling shows.
        d.line(c, camera.to_screen(pose.to_world({g.radius, 0})), 2.0f, edge);
        break;
      }
      case tire::PropShape::chain: {
        // Terrain, solid on the side opposite its edge normals. An edge that faces up is filled
        // down to the floor, like the ground, and rock under it to the bottom of the view; any
        // other edge (a wall, an overhang) is thickened by the chain's thickness, with mitred
        // joints. Then the surface line.
        const std::size_t count = g.vertices.size();
        const std::size_t edges = std::min(g.loop ? count : count - 1, g.normals.size());
        const double depth = std::max(g.thickness, 0.1);
        const bool terrain = g.type == tire::PropType::static_body;
        const SDL_Color body = terrain ? kEarth : darker(fill, 0.85f);
        const auto vertex_offset = [&](std::size_t v) {
          const bool has_prev = edges > 0 && (g.loop || v > 0), has_next = v < edges;
          const tire::Vec2 prev = has_prev ? g.normals[(v + edges - 1) % edges] : tire::Vec2{};
          const tire::Vec2 next = has_next ? g.normals[v] : tire::Vec2{};
          tire::Vec2 n = prev + next;
          const double len = length(n);
          if (len <= 0.0) return tire::Vec2{};
          n = n / len;
          return n * (depth / std::max(0.35, dot(n, has_next ? next : prev)));
        };
        for (std::size_t e = 0; e < edges; ++e) {
          const std::size_t f = (e + 1) % count;
          const tire::Vec2 a = pose.to_world(g.vertices[e]), b = pose.to_world(g.vertices[f]);
          const tire::Vec2 n = pose.rotate(g.normals[e]);
          const double bottom = camera.view().min.y;
          if (terrain && n.y > 0.3 && floor_ < std::min(a.y, b.y)) {
            d.quad(camera.to_screen(a), camera.to_screen(b), camera.to_screen({b.x, floor_}),
                   camera.to_screen({a.x, floor_}), body);
            if (floor_ > bottom)
              d.rect(camera.to_screen({a.x, floor_}), camera.to_screen({b.x, bottom}), kBedrock);
          } else if (terrain && n.y > 0.3 && std::min(a.y, b.y) > bottom) {
            d.quad(camera.to_screen(a), camera.to_screen(b), camera.to_screen({b.x, bottom}),
                   camera.to_screen({a.x, bottom}), kBedrock);
          } else {
            d.quad(camera.to_screen(a), camera.to_screen(b),
                   camera.to_screen(pose.to_world(g.vertices[f] - vertex_offset(f))),
                   camera.to_screen(pose.to_world(g.vertices[e] - vertex_offset(e))), body);
          }
        }
        d.polyline(shape_, g.loop, std::max(3.0f, camera.pixels(0.08)), terrain ? kGrass : fill);
        break;
      }
    }
  }
}

void WorldRenderer::draw_goal(Draw& d, const Camera& camera, const tire::Simulation& simulation) {
  const std::optional<std::size_t> goal_index = simulation.goal();
  if (!goal_index) return;
  const tire::Region& goal = simulation.regions()[*goal_index];
  const ScreenPoint a = camera.to_screen(goal.box.min), b = camera.to_screen(goal.box.max);
  d.rect(a, b, rgba(80, 220, 110, 46));
  d.rect_outline(a, b, 1.5f, rgba(40, 160, 70, 120));
  // A chequered flag on a pole in the middle of the region.
  const double height = std::min(goal.box.max.y - goal.box.min.y, 2.5);
  const tire::Vec2 base{0.5 * (goal.box.min.x + goal.box.max.x), goal.box.min.y};
  const tire::Vec2 top = base + tire::Vec2{0, height};
  d.line(camera.to_screen(base), camera.to_screen(top), std::max(2.0f, camera.pixels(0.05)),
         rgba(70, 70, 70));
  const double fw = 0.8, fh = 0.5, cell = 0.1;
  for (int i = 0; i < static_cast<int>(fw / cell + 0.5); ++i)
    for (int j = 0; j < static_cast<int>(fh / cell + 0.5); ++j) {
      const tire::Vec2 m = top + tire::Vec2{i * cell, -(j + 1) * cell};
      d.rect(camera.to_screen(m), camera.to_screen(m + tire::Vec2{cell, cell}),
             (i + j) % 2 ? rgba(20, 20, 20) : rgba(250, 250, 250));
    }
}

void WorldRenderer::draw_tire(Draw& d, const Camera& camera, const GameSession& session,
                              const tire::TireView& t, double alpha, bool is_player, bool shaded) {
  const auto shade = [shaded](SDL_Color c) { return shaded ? asleep_shade(c) : c; };
  session.interpolated_positions(t, alpha, positions_);
  const std::uint32_t n = t.segments;
  tire::Vec2 hub_world;
  for (std::uint32_t i = 0; i < 2 * n; ++i) hub_world += positions_[i];
  hub_world = hub_world / static_cast<double>(2 * n);
  const ScreenPoint hub = camera.to_screen(hub_world);
  // Level of detail: the rings are drawn through every `step`-th particle, so that the drawn tread
  // segments are about kMinSegmentPixels long on screen or longer (at least 8 points a ring). A pile
  // of small tires then costs a fraction of the triangles and looks the same.
  const float segment_px = camera.pixels(2.0 * std::numbers::pi * t.outer_radius / n);
  const std::uint32_t step = std::clamp<std::uint32_t>(
      segment_px > 0.0f ? static_cast<std::uint32_t>(std::lround(kMinSegmentPixels / segment_px)) : n, 1u,
      std::max(1u, n / 8));
  outer_.clear();
  inner_.clear();
  for (std::uint32_t i = 0; i < n; i += step) {
    outer_.push_back(camera.to_screen(positions_[i]));
    inner_.push_back(camera.to_screen(positions_[n + i]));
  }
  const auto m = static_cast<std::uint32_t>(outer_.size());
  // A reduced tire is one fan of triangles over its tread, textured with a picture of the tire:
  // particle i keeps its place in the picture, so the picture turns and squashes with the tire.
  if (step > 1)
    if (TireTexture* tex = tire_texture(d.renderer(), t, camera.pixels(t.outer_radius), is_player)) {
      // Where drawn point k sits in the picture; the same for every tire of this segment count.
      const float uv_radius = 0.5f - 1.0f / static_cast<float>(tex->size);
      if (uv_.size() != m || uv_segments_ != n || uv_step_ != step || uv_radius_ != uv_radius) {
        uv_.clear();
        for (std::uint32_t i = 0; i < n; i += step) {
          const double a = 2.0 * std::numbers::pi * i / n;
          uv_.push_back({0.5f + uv_radius * static_cast<float>(std::cos(a)),
                         0.5f + uv_radius * static_cast<float>(std::sin(a))});
        }
        uv_segments_ = n, uv_step_ = step, uv_radius_ = uv_radius;
      }
      // The vertex colour multiplies the picture's.
      const SDL_Color tint = shade(rgba(255, 255, 255));
      const auto vertex = [tint](ScreenPoint p, SDL_FPoint uv) {
        SDL_Vertex out{};
        out.position = {p.x, p.y};
        out.color = tint;
        out.tex_coord = uv;
        return out;
      };
      const SDL_Vertex centre = vertex(hub, {0.5f, 0.5f});
      for (std::uint32_t k = 0; k < m; ++k) {
        const std::uint32_t l = k + 1 == m ? 0 : k + 1;
        tex->vertices.push_back(centre);
        tex->vertices.push_back(vertex(outer_[k], uv_[k]));
        tex->vertices.push_back(vertex(outer_[l], uv_[l]));
      }
      if (t.grab) d.polyline(outer_, true, 2.5f, rgba(255, 230, 90));
      return;
    }
  // Sidewall: the whole tire as a fan from the hub over the tread.
  d.fan(hub, outer_, shade(kSidewall));
  // Tread: a band along the outer ring in alternating blocks, which turn as the tire rolls. The
  // dark blocks are barely darker than the sidewall: only a tire drawn in full detail gets them.
  band_.resize(m);
  for (std::uint32_t i = 0; i < m; ++i) band_[i] = lerp(outer_[i], inner_[i], 0.42f);
  for (std::uint32_t i = 0; i < m; ++i) {
    const std::uint32_t j = (i + 1) % m;
    if (i % 2)
      d.quad(outer_[i], outer_[j], band_[j], band_[i], shade(kTreadLight));
    else if (step == 1)
      d.quad(outer_[i], outer_[j], band_[j], band_[i], shade(kTreadDark));
  }
  // Rim, with spokes and a hub cap. In full detail the rim has a dark edge (a fan under a fan 1.5 px
  // smaller) and four spokes; a reduced tire, small on screen, gets a plain rim and two spokes
  // across it.
  const SDL_Color rim = shade(is_player ? kRimPlayer : kRimOther);
  if (step == 1) {
    d.fan(hub, inner_, darker(rim, 0.55f));
    for (ScreenPoint& p : inner_) {
      const float dx = p.x - hub.x, dy = p.y - hub.y;
      const float len = std::sqrt(dx * dx + dy * dy);
      const float k = len > 3.0f ? (len - 1.5f) / len : 0.5f;
      p = {hub.x + dx * k, hub.y + dy * k};
    }
  }
  d.fan(hub, inner_, rim);
  const float spoke_width = std::max(2.0f, camera.pixels(t.inner_radius * 0.12));
  if (m >= 4) {
    if (step == 1)
      for (std::uint32_t k = 0; k < 4; ++k) d.line(hub, inner_[k * m / 4], spoke_width, darker(rim, 0.7f));
    else
      for (std::uint32_t k = 0; k < 2; ++k)
        d.line(inner_[k * m / 4], inner_[(k + 2) * m / 4], spoke_width, darker(rim, 0.7f));
  }
  // The cap: a circle of about one triangle per 1.5 px of radius, 4 to 16.
  const float cap = std::max(2.0f, camera.pixels(t.inner_radius * 0.3));
  d.circle(hub, cap, shade(kHubCap), std::clamp(static_cast<int>(cap / 1.5f), 4, 16));
  if (t.grab) d.polyline(outer_, true, 2.5f, rgba(255, 230, 90));
}

void WorldRenderer::draw_heads(Draw& d, const Camera& camera, const GameSession& session, double alpha) {
  const tire::Simulation& simulation = session.simulation();
  for (std::size_t i = 0; const std::optional<tire::VehicleView> v = simulation.vehicle_at(i); ++i) {
    if (!v->head_center) continue;
    // On the chassis as drawn (blended between ticks), where the engine has it on the chassis now.
    const tire::Pose chassis = session.interpolated_pose(v->chassis, alpha);
    const tire::Vec2 local = head_local(v->pose, *v->head_center);
    draw_helmet(d, camera, chassis, local, v->head_radius, v->player ? player_helmet() : other_helmet(),
                shape_);
  }
}

void WorldRenderer::draw_grab(Draw& d, const Camera& camera, const GameSession& session, double alpha) {
  const tire::Simulation& simulation = session.simulation();
  for (std::size_t i = 0; const std::optional<tire::TireView> t = simulation.tire_at(i); ++i) {
    if (!t->grab) continue;
    session.interpolated_positions(*t, alpha, positions_);
    const ScreenPoint from = camera.to_screen(positions_[t->grab->particle]);
    const ScreenPoint to = camera.to_screen(t->grab->target);
    d.line(from, to, 2.0f, rgba(255, 230, 90));
    d.circle(to, 5.0f, rgba(255, 230, 90), 12);
    d.circle(from, 4.0f, rgba(230, 80, 40), 12);
  }
}

void WorldRenderer::draw_debug(Draw& d, const Camera& camera, const GameSession& session, double alpha,
                               const DebugOptions& debug) {
  const tire::Simulation& simulation = session.simulation();
  ImDrawList* labels = ImGui::GetBackgroundDrawList();

  if (debug.regions)
    for (const tire::Region& r : simulation.regions()) {
      const ScreenPoint a = camera.to_screen({r.box.min.x, r.box.max.y});
      d.rect_outline(a, camera.to_screen({r.box.max.x, r.box.min.y}), 1.5f, rgba(40, 70, 220, 200));
      labels->AddText({a.x + 4, a.y + 2}, IM_COL32(30, 50, 200, 255), r.name.c_str());
    }

  // The level's bounds (a computed top is open: drawn at the top of the view).
  if (const std::optional<tire::Aabb> b = simulation.bounds()) {
    const tire::Aabb view = camera.view();
    const tire::Vec2 hi{b->max.x, std::min(b->max.y, view.max.y + 1.0)};
    d.rect_outline(camera.to_screen(b->min), camera.to_screen(hi), 2.0f, rgba(220, 50, 40, 200));
  }

  // What the engine shows of its own state (debug_draw_sdl.h).
  SdlDebugDraw shapes(d, camera, session, alpha, positions_, shape_);
  shapes.set_flags(debug_flags(debug));
  simulation.debug_draw(shapes);
}

}  // namespace game

#include "figure/figure_layout.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <limits>
#include <memory>

#include "figure/text_metrics.h"

namespace raycam::figure {

const char* const kFont = "DejaVu Sans";

namespace {

constexpr double kPointsPerMm = 72.0 / 25.4;
constexpr double kLineSpacing = 1.25;       // a text line's height, in font sizes
constexpr double kCaptionSpacing = 1.45;    // a caption's lines: room for the arrows over vectors and scripts
constexpr double kTitleScale = 1.3;         // the title's size, in font sizes
constexpr double kMinTickGap = 2.0;         // pt: closer ticks merge into a bar; keep every k-th
constexpr double kTickHalfLength = 2.5;     // pt
// A label over an object costs more than one over a ray; enough that the free labels, placed after the
// names, go round the objects rather than over them.
constexpr double kOverObjectWeight = 150.0;
constexpr std::size_t kObjectNamesUpTo = 40;  // beyond, names would cover the drawing (all objects drawn)
// An object's name, in font sizes: its gaps to its own rim, the farthest it sits from it without a leader,
// how much nearer than any other object its own must be (an eye does not weigh a point either way; and at
// most half as far), and its clearance to other objects and to the crosses, ticks and the camera.
constexpr double kNameGaps[] = {0.15, 0.45};
constexpr double kNameReach = 0.6;
constexpr double kNameMargin = 0.3;
constexpr double kNameClearance = 0.25;
constexpr int kLeaderGrid = 90;  // free places tried for a leader's name, per side of the drawing at most

// ---- geometry --------------------------------------------------------------------------------------------

Box grown(const Box& b, double by) { return {b.left - by, b.top - by, b.right + by, b.bottom + by}; }

bool inside(const Box& b, glm::dvec2 p) { return p.x >= b.left && p.x <= b.right && p.y >= b.top && p.y <= b.bottom; }

// The parameters [t0, t1] of segment a-b inside the box (Liang–Barsky clipping); false when it misses.
bool clip_segment(glm::dvec2 a, glm::dvec2 b, const Box& box, double& t0, double& t1) {
  t0 = 0.0;
  t1 = 1.0;
  const glm::dvec2 d = b - a;
  const double p[] = {-d.x, d.x, -d.y, d.y};
  const double q[] = {a.x - box.left, box.right - a.x, a.y - box.top, box.bottom - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0.0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
    if (t0 > t1) return false;
  }
  return true;
}

// The length of segment a-b inside the box.
double length_inside(glm::dvec2 a, glm::dvec2 b, const Box& box) {
  double t0, t1;
  return clip_segment(a, b, box, t0, t1) ? (t1 - t0) * glm::length(b - a) : 0.0;
}

// The part of the box a disc covers, sampled on a 5 × 3 grid (exact enough to rank candidate places).
double disc_cover(const PageDisc& disc, const Box& box) {
  const double nx = std::clamp(disc.centre.x, box.left, box.right), ny = std::clamp(disc.centre.y, box.top, box.bottom);
  if (glm::length(glm::dvec2(nx, ny) - disc.centre) >= disc.radius) return 0.0;
  int inside = 0;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 3; ++j) {
      const glm::dvec2 p(box.left + (i + 0.5) / 5.0 * box.width(), box.top + (j + 0.5) / 3.0 * box.height());
      inside += glm::length(p - disc.centre) < disc.radius;
    }
  return inside / 15.0 * box.width() * box.height();
}

glm::dvec2 nearest_point(const Box& b, glm::dvec2 p) {
  return {std::clamp(p.x, b.left, b.right), std::clamp(p.y, b.top, b.bottom)};
}

// ---- text -----------------------------------------------------------------------------------------------

PlacedText text_at(const std::string& markup, glm::dvec2 at, double size, bool bold) {
  const TextExtent e = measure_text(markup, size, bold);
  PlacedText t;
  t.markup = markup;
  t.at = at;
  t.size = size;
  t.bold = bold;
  t.box = {at.x, at.y - e.above, at.x + e.width, at.y + e.below};
  t.anchor = at;
  return t;
}

// Splits at spaces outside $…$ (a formula is never broken), within `width`.
std::vector<std::string> wrap(const std::string& markup, double width, double size) {
  std::vector<std::string> words(1);
  bool math = false;
  for (std::size_t i = 0; i < markup.size(); ++i) {
    const char c = markup[i];
    if (c == '\\' && i + 1 < markup.size()) {
      words.back() += markup.substr(i, 2);
      ++i;
      continue;
    }
    if (c == '$') math = !math;
    if (c == ' ' && !math)
      words.emplace_back();
    else
      words.back() += c;
  }
  std::vector<std::string> lines(1);
  for (const std::string& word : words) {
    const std::string candidate = lines.back().empty() ? word : lines.back() + " " + word;
    if (!lines.back().empty() && measure_text(candidate, size).width > width)
      lines.push_back(word);
    else
      lines.back() = candidate;
  }
  return lines;
}

// ---- the bands ------------------------------------------------------------------------------------------

struct Bands {
  double margin, font, line;
  Box area;
  double caption_top, matrix_top;
  int caption_lines;
  double room;  // the drawing's height before the least share is given to it
};

Bands bands_of(const Figure& figure, const FigureOutput& output) {
  Bands b;
  b.font = output.font_size_pt;
  b.line = kLineSpacing * b.font;
  b.margin = std::max(4.0, b.font);
  const double width = output.page.width_pt - 2.0 * b.margin;
  double y = b.margin;
  if (output.title) y += 1.5 * kTitleScale * b.font;
  b.caption_top = y;
  b.caption_lines = 0;
  if (output.caption)
    for (const Frame& frame : figure.frames)
      b.caption_lines = std::max(b.caption_lines, int(wrap(frame.caption, width, b.font).size()));
  y += b.caption_lines * kCaptionSpacing * b.font + 0.5 * b.font;
  int rows = 0;
  if (output.matrix)
    for (const Frame& frame : figure.frames) rows = std::max(rows, frame.matrix_size);
  const double bottom = output.page.height_pt - b.margin - (rows > 0 ? rows * b.line + 0.5 * b.font : 0.0);
  b.matrix_top = bottom + 0.5 * b.font;
  // A page too small for its text still gets a drawing (the text then runs over it; the command refuses).
  const double min_height = kLeastDrawingShare * output.page.height_pt;
  b.room = bottom - y;
  b.area = {b.margin, y, output.page.width_pt - b.margin, std::max(bottom, y + min_height)};
  return b;
}

PageTransform transform_of(const Frame& frame, const Box& area) {
  const glm::dvec2 extent = glm::max(frame.plane_max - frame.plane_min, glm::dvec2(1e-300));
  PageTransform t;
  t.scale = std::min(area.width() / extent.x, area.height() / extent.y);
  const glm::dvec2 middle = 0.5 * (frame.plane_min + frame.plane_max);
  t.x0 = 0.5 * (area.left + area.right) - t.scale * middle.x;
  t.y0 = 0.5 * (area.top + area.bottom) + t.scale * middle.y;
  return t;
}

// ---- primitives -----------------------------------------------------------------------------------------

// The pixels' ticks, every k-th (the first and the last always) so that they stay kMinTickGap apart.
void add_segments(const Frame& frame, const PageTransform& to_page, PageFrame& page) {
  std::vector<Segment> ticks;
  // Cut to the drawing area (and a little more, for the strokes' ends): a ray of 4·10⁵ units would overflow
  // cairo's fixed-point coordinates, and lines nobody sees would only weigh on the file.
  const Box kept = grown(page.area, 20.0);
  for (const Segment& s : frame.segments) {
    Segment moved{to_page(s.from), to_page(s.to), s.stroke};
    if (s.stroke == Stroke::tick) {  // a fixed length across the screen, whatever the scale
      const glm::dvec2 across = kTickHalfLength * glm::normalize(moved.to - moved.from + 1e-300);
      if (inside(kept, moved.from)) ticks.push_back({moved.from - across, moved.from + across, Stroke::tick});
      continue;
    }
    double t0, t1;
    if (!clip_segment(moved.from, moved.to, kept, t0, t1)) continue;
    const glm::dvec2 along = moved.to - moved.from;
    moved.to = moved.from + t1 * along;
    moved.from = moved.from + t0 * along;
    page.segments.push_back(moved);
  }
  if (ticks.empty()) return;
  const double gap = ticks.size() > 1 ? glm::length(ticks[1].from - ticks[0].from) : kMinTickGap;
  const std::size_t every = std::max<std::size_t>(1, std::size_t(std::ceil(kMinTickGap / std::max(gap, 1e-12) - 1e-9)));
  const std::size_t last = ticks.size() - 1;
  for (std::size_t i = 0; i <= last; ++i)
    if (i == last || (i % every == 0 && (i == 0 || last - i >= every)))
      page.segments.push_back(ticks[i]);
}

// The objects that reach the drawing area (the others would only weigh on the file and overflow TeX's
// dimensions); a disc too big for the page's numbers becomes the polygon of its visible part.
// Returns, per object of the frame, its index in page.discs (-1: not drawn).
std::vector<int> add_discs(const Frame& frame, PageFrame& page) {
  std::vector<int> drawn(frame.objects.size(), -1);
  constexpr double kHugeRadius = 1e4;  // pt: beyond, the outline is a polygon
  const Box kept = grown(page.area, 20.0);
  const glm::dvec2 middle(0.5 * (kept.left + kept.right), 0.5 * (kept.top + kept.bottom));
  const double half_diagonal = 0.5 * std::hypot(kept.width(), kept.height());
  for (std::size_t i = 0; i < frame.objects.size(); ++i) {
    const Disc& disc = frame.objects[i];
    PageDisc d{page.to_page(disc.centre), page.to_page.scale * disc.radius, disc.colour, {}};
    if (glm::length(nearest_point(kept, d.centre) - d.centre) > d.radius) continue;  // misses the area
    const double distance = glm::length(d.centre - middle);
    if (distance + half_diagonal < d.radius && d.radius > kHugeRadius) {  // covers it all
      d.outline = {{kept.left, kept.top}, {kept.right, kept.top}, {kept.right, kept.bottom}, {kept.left, kept.bottom}};
    } else if (d.radius > kHugeRadius) {  // its rim crosses the area: the arc there, closed inside the disc
      const glm::dvec2 towards = (middle - d.centre) / std::max(distance, 1e-300);
      const double angle = std::atan2(towards.y, towards.x);
      const double span = 2.0 * half_diagonal / d.radius;
      constexpr int kSteps = 64;
      for (int k = 0; k <= kSteps; ++k) {
        const double a = angle - span + 2.0 * span * k / kSteps;
        d.outline.push_back(d.centre + d.radius * glm::dvec2(std::cos(a), std::sin(a)));
      }
      d.outline.push_back(d.outline.back() - 4.0 * half_diagonal * towards);
      d.outline.insert(d.outline.begin(), d.outline.front() - 4.0 * half_diagonal * towards);
    }
    drawn[i] = int(page.discs.size());
    page.discs.push_back(std::move(d));
  }
  return drawn;
}

// ---- the inset -----------------------------------------------------------------------------------------

struct PlaneBounds {
  glm::dvec2 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
  void add(glm::dvec2 p, double r = 0.0) {
    lo = glm::min(lo, p - r);
    hi = glm::max(hi, p + r);
  }
  bool holds(glm::dvec2 p) const { return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y; }
};

// What covering `box` would hide of the main drawing: the points above all, then rays and discs.
double inset_cost(const PageFrame& page, const Box& box) {
  double cost = 0.0;
  for (const PageMarker& m : page.markers) cost += inside(grown(box, page.arm), m.at) ? 1e9 : 0.0;
  for (const Segment& s : page.segments) cost += page.font_size * length_inside(s.from, s.to, box);
  for (const PageDisc& d : page.discs) cost += disc_cover(d, box);
  return cost;
}

// The overview of the whole scene, in the corner where it hides the least (the labels, placed next, avoid it).
void add_inset(const Frame& frame, PageFrame& page) {
  if (frame.objects_faded || frame.objects.empty()) return;
  const PageTransform& t = page.to_page;
  PlaneBounds view;  // the plane region the drawing area shows
  view.add({(page.area.left - t.x0) / t.scale, (t.y0 - page.area.bottom) / t.scale});
  view.add({(page.area.right - t.x0) / t.scale, (t.y0 - page.area.top) / t.scale});
  PlaneBounds scene;
  bool cut = false;
  for (const Disc& disc : frame.objects) {
    scene.add(disc.centre, disc.radius);
    cut = cut || !view.holds(disc.centre);
  }
  for (const Marker& m : frame.markers) scene.add(m.at);
  const glm::dvec2 extent = glm::max(scene.hi - scene.lo, glm::dvec2(1e-300)), shown = view.hi - view.lo;
  const bool small = std::max(shown.x / extent.x, shown.y / extent.y) < kInsetBelowShare;
  if (!cut && !small) return;

  PageInset& inset = page.inset;
  const double w = kInsetSize * page.area.width(), h = kInsetSize * page.area.height(), gap = 2.0;
  double best = std::numeric_limits<double>::infinity();
  for (int corner = 0; corner < 4; ++corner) {
    const double left = corner % 2 ? page.area.right - gap - w : page.area.left + gap;
    const double top = corner / 2 ? page.area.bottom - gap - h : page.area.top + gap;
    const Box box{left, top, left + w, top + h};
    const double cost = inset_cost(page, box) + 1e-3 * corner;  // ties: the upper left first
    if (cost < best) {
      best = cost;
      inset.box = box;
    }
  }
  const Box inner = grown(inset.box, -0.06 * std::min(w, h));
  inset.to_inset.scale = std::min(inner.width() / extent.x, inner.height() / extent.y);
  const glm::dvec2 middle = 0.5 * (scene.lo + scene.hi);
  inset.to_inset.x0 = 0.5 * (inner.left + inner.right) - inset.to_inset.scale * middle.x;
  inset.to_inset.y0 = 0.5 * (inner.top + inner.bottom) + inset.to_inset.scale * middle.y;
  const PageTransform& to = inset.to_inset;
  for (const Disc& disc : frame.objects)
    inset.discs.push_back({to(disc.centre), std::max(0.6, to.scale * disc.radius), disc.colour, {}});
  glm::dvec2 ends[2];
  for (const Marker& m : frame.markers) {
    if (m.point == Point::eye || m.point == Point::target) inset.crosses.push_back(to(m.at));
    if (m.point == Point::screen_first_end) ends[0] = to(m.at);
    if (m.point == Point::screen_last_end) ends[1] = to(m.at);
  }
  inset.screen.push_back({ends[0], ends[1], Stroke::camera});
  // The zoomed region, at least a few points wide so that it shows on a scene a thousand times larger.
  const glm::dvec2 a = to(view.lo), b = to(view.hi), c = 0.5 * (a + b);
  const double half_w = std::max(0.5 * std::abs(b.x - a.x), 2.0), half_h = std::max(0.5 * std::abs(b.y - a.y), 2.0);
  inset.zoom = {c.x - half_w, c.y - half_h, c.x + half_w, c.y + half_h};
}

// ---- label placement ------------------------------------------------------------------------------------

struct Request {
  std::string markup;
  glm::dvec2 anchor;
  bool bold;
};

bool same(const Box& a, const Box& b) {
  return a.left == b.left && a.top == b.top && a.right == b.right && a.bottom == b.bottom;
}

bool is_solid(Stroke s) { return s == Stroke::camera || s == Stroke::arrow || s == Stroke::tick; }

double box_to_point(const Box& b, glm::dvec2 p) { return glm::length(p - nearest_point(b, p)); }

// The gap between a box and a disc (0 when they meet).
double box_to_disc(const Box& b, const PageDisc& d) { return std::max(0.0, box_to_point(b, d.centre) - d.radius); }

double segment_to_point(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
  const glm::dvec2 d = b - a;
  const double t = glm::dot(d, d) > 0.0 ? std::clamp(glm::dot(p - a, d) / glm::dot(d, d), 0.0, 1.0) : 0.0;
  return glm::length(a + t * d - p);
}

bool segments_cross(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 d) {
  auto side = [](glm::dvec2 o, glm::dvec2 p, glm::dvec2 q) {
    const glm::dvec2 u = p - o, v = q - o;
    return u.x * v.y - u.y * v.x;
  };
  return side(a, b, c) * side(a, b, d) <= 0.0 && side(c, d, a) * side(c, d, b) <= 0.0;
}

class Placer {
 public:
  Placer(PageFrame& page, double font) : page_(page), font_(font) {
    for (const Segment& s : page.segments) {
      lines_.push_back({s.from, s.to});
      if (is_solid(s.stroke)) solid_.push_back({s.from, s.to});
    }
    for (const PageMarker& m : page.markers) {  // the crosses
      for (const glm::dvec2 arm : {glm::dvec2(page.arm, 0.0), glm::dvec2(0.0, page.arm)}) {
        lines_.push_back({m.at - arm, m.at + arm});
        solid_.push_back({m.at - arm, m.at + arm});
      }
    }
  }

  void place(const Request& request) {
    const TextExtent e = measure_text(request.markup, font_, request.bold);
    const double gap = page_.arm + 0.25 * font_;
    static const glm::dvec2 kDirections[] = {{1, -1}, {1, 0}, {-1, -1}, {0, -1}, {1, 1}, {-1, 0}, {0, 1}, {-1, 1}};
    const double kRings[] = {1.0, 2.5, 4.5};
    double best_cost = std::numeric_limits<double>::infinity();
    PlacedText best;
    for (int ring = 0; ring < 3; ++ring)
      for (int d = 0; d < 8; ++d) {
        glm::dvec2 dir = kDirections[d];
        if (dir.x != 0.0 && dir.y != 0.0) dir *= 0.7071;
        const glm::dvec2 p = request.anchor + kRings[ring] * gap * dir;
        const double ax = 0.5 * (1.0 - kDirections[d].x), ay = 0.5 * (1.0 + kDirections[d].y);
        const double h = e.above + e.below;
        const Box b{p.x - ax * e.width, p.y - ay * h, p.x - ax * e.width + e.width, p.y - ay * h + h};
        double cost = cost_of(b) + 3.0 * font_ * font_ * ring + 0.05 * d;
        if (ring > 0) cost += crossing_names(request.anchor, nearest_point(b, request.anchor));
        if (cost < best_cost) {
          best_cost = cost;
          best = PlacedText{request.markup, {b.left, b.top + e.above}, font_, request.bold, b, ring > 0, request.anchor};
        }
      }
    if (best.leader) {
      const std::pair<glm::dvec2, glm::dvec2> leader{request.anchor, nearest_point(best.box, request.anchor)};
      lines_.push_back(leader);
      solid_.push_back(leader);
      leaders_.push_back(leader);
    }
    page_.labels.push_back(best);
  }

  // The places by disc `own` where its name lies on nothing else and nearer to it than to any other object,
  // best first (cheapest: the fewest rays crossed, the upper right).
  std::vector<PlacedText> places_by(const std::string& markup, std::size_t own) const {
    const TextExtent e = measure_text(markup, font_, false);
    const PageDisc& disc = page_.discs[own];
    std::vector<std::pair<double, PlacedText>> found;
    constexpr int kAngles = 24;
    for (int g = 0; g < 2; ++g)
      for (int k = 0; k < kAngles; ++k) {
        // From the upper right (−45° on the page, y down) both ways round.
        const double turn = (k % 2 ? -1.0 : 1.0) * ((k + 1) / 2) * glm::two_pi<double>() / kAngles;
        const double angle = -0.25 * glm::pi<double>() + turn;
        const glm::dvec2 dir(std::cos(angle), std::sin(angle));
        const double want = disc.radius + kNameGaps[g] * font_;
        const glm::dvec2 q = disc.centre + want * dir;
        // The box on the far side of q, its nearest part towards the disc.
        const double fx = 0.5 * (1.0 - std::clamp(1.4142 * dir.x, -1.0, 1.0));
        const double fy = 0.5 * (1.0 - std::clamp(1.4142 * dir.y, -1.0, 1.0));
        const double h = e.above + e.below;
        Box b{q.x - fx * e.width, q.y - fy * h, q.x - fx * e.width + e.width, q.y - fy * h + h};
        for (int push = 0; push < 4; ++push) {  // off the rim, along dir
          const double short_by = want - box_to_point(b, disc.centre);
          if (short_by <= 1e-9) break;
          const glm::dvec2 by = short_by * dir;
          b = {b.left + by.x, b.top + by.y, b.right + by.x, b.bottom + by.y};
        }
        if (box_to_point(b, disc.centre) < disc.radius + 0.5 * kNameGaps[0] * font_) continue;
        if (!free_for_name(b, own, false)) continue;
        const double mine = box_to_disc(b, disc);
        if (mine > kNameReach * font_) continue;
        bool nearest = true;
        for (std::size_t j = 0; j < page_.discs.size() && nearest; ++j)
          nearest = j == own || box_to_disc(b, page_.discs[j]) >= std::max(mine + kNameMargin * font_, 2.0 * mine);
        if (!nearest) continue;
        double cost = font_ * std::abs(turn) / glm::pi<double>() + 2.0 * font_ * g;
        const Box halo = grown(b, 0.8);
        for (const auto& [a, c] : lines_) cost += 4.0 * length_inside(a, c, halo);
        found.push_back({cost, PlacedText{markup, {b.left, b.top + e.above}, font_, false, b, false, disc.centre}});
      }
    std::stable_sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<PlacedText> places;
    for (auto& f : found) places.push_back(std::move(f.second));
    return places;
  }

  // A free place anywhere in the drawing with a leader to a dot on disc `own` that crosses no other object,
  // label or leader: the shortest leader, the fewest lines crossed. False when there is none.
  bool place_on_leader(const std::string& markup, std::size_t own) {
    const TextExtent e = measure_text(markup, font_, false);
    const PageDisc& disc = page_.discs[own];
    const Box& area = page_.area;
    const double w = e.width, h = e.above + e.below;
    const Box inner = grown(area, -1.0);
    const double step_x = std::max(0.5 * font_, (area.width() - w) / kLeaderGrid);
    const double step_y = std::max(0.5 * font_, (area.height() - h) / kLeaderGrid);
    double best_cost = std::numeric_limits<double>::infinity();
    PlacedText best;
    for (double top = area.top; top + h <= area.bottom; top += step_y)
      for (double left = area.left; left + w <= area.right; left += step_x) {
        const Box b{left, top, left + w, top + h};
        const glm::dvec2 towards = nearest_point(b, disc.centre) - disc.centre;
        const double far = glm::length(towards);
        if (far <= 0.0) continue;
        // The dot just inside the rim facing the box (at the centre of a small disc), in view.
        const double in = std::max(0.0, disc.radius - std::max(1.5, 0.25 * disc.radius));
        const glm::dvec2 dot = disc.centre + std::min(in, far) * towards / far;
        if (!inside(inner, dot)) continue;
        const glm::dvec2 end = nearest_point(b, dot);
        const double length = glm::length(end - dot);
        if (length >= best_cost) continue;  // the cost is at least the leader's length
        if (!free_for_name(b, own, true) || !clear_leader(dot, end, own)) continue;
        double cost = length;
        for (const auto& [a, c] : lines_) cost += segments_cross(dot, end, a, c) ? 2.0 * font_ : 0.0;
        const Box halo = grown(b, 0.8);
        for (const auto& [a, c] : lines_) cost += 4.0 * length_inside(a, c, halo);
        if (cost < best_cost) {
          best_cost = cost;
          best = PlacedText{markup, {b.left, b.top + e.above}, font_, false, b, true, dot, true};
        }
      }
    if (!std::isfinite(best_cost)) return false;
    add_leader(best.anchor, nearest_point(best.box, best.anchor));
    add(best);
    return true;
  }

  // Whether the name of disc `own` still lies on nothing, its leader crossing nothing; if not, it is taken
  // away (its leader too), to be placed again.
  bool still_free(const std::string& markup, std::size_t own) {
    const PageDisc& disc = page_.discs[own];
    auto is_the_name = [&](const PlacedText& label) {  // its anchor on its disc: two objects may share a name
      return label.markup == markup && glm::length(label.anchor - disc.centre) <= disc.radius + 1e-9;
    };
    std::size_t k = 0;
    while (k < page_.labels.size() && !is_the_name(page_.labels[k])) ++k;
    if (k == page_.labels.size()) return true;
    const PlacedText name = page_.labels[k];
    page_.labels.erase(page_.labels.begin() + std::ptrdiff_t(k));
    names_.erase(std::find_if(names_.begin(), names_.end(), [&](const Box& b) { return same(b, name.box); }));
    const std::pair<glm::dvec2, glm::dvec2> leader{name.anchor, nearest_point(name.box, name.anchor)};
    if (name.leader)
      for (auto* lines : {&lines_, &solid_, &leaders_, &name_leaders_})
        lines->erase(std::find(lines->begin(), lines->end(), leader));
    if (free_for_name(name.box, own, name.leader) && (!name.leader || clear_leader(leader.first, leader.second, own))) {
      if (name.leader) add_leader(leader.first, leader.second);
      add(name);
      return true;
    }
    return false;
  }

  void add(const PlacedText& name) {
    page_.labels.push_back(name);
    names_.push_back(name.box);
  }

 private:
  void add_leader(glm::dvec2 a, glm::dvec2 b) {  // a name's
    for (auto* lines : {&lines_, &solid_, &leaders_, &name_leaders_}) lines->push_back({a, b});
  }

  // Nothing but rays and construction lines under a name's box: inside the drawing, off the inset, the other
  // labels, the other objects (and its own, `own_too`), the camera, the crosses and the leaders.
  bool free_for_name(const Box& box, std::size_t own, bool own_too) const {
    const Box& area = page_.area;
    if (box.left < area.left || box.right > area.right || box.top < area.top || box.bottom > area.bottom) return false;
    if (page_.inset.shown() && overlap_area(grown(page_.inset.box, 0.3 * font_), box) > 0.0) return false;
    for (const PlacedText& other : page_.labels)
      if (overlap_area(grown(other.box, 0.3 * font_), box) > 0.0) return false;
    for (std::size_t j = 0; j < page_.discs.size(); ++j)
      if ((j != own || own_too) && box_to_disc(box, page_.discs[j]) < kNameClearance * font_) return false;
    const Box halo = grown(box, 0.8);
    for (const auto& [a, b] : solid_)
      if (length_inside(a, b, halo) > 0.0) return false;
    return true;
  }

  // A leader a reader can follow: over no other object, label, leader, cross or camera line.
  bool clear_leader(glm::dvec2 dot, glm::dvec2 end, std::size_t own) const {
    for (std::size_t j = 0; j < page_.discs.size(); ++j)
      if (j != own && segment_to_point(dot, end, page_.discs[j].centre) < page_.discs[j].radius + 1.0) return false;
    for (const PlacedText& other : page_.labels)
      if (length_inside(dot, end, grown(other.box, 1.0)) > 0.0) return false;
    for (const auto& [a, b] : solid_)  // the leaders, the camera, the ticks, the crosses
      if (segments_cross(dot, end, a, b)) return false;
    return true;
  }

  // A label's leader over a name or across a leader: a reader would follow the wrong one.
  double crossing_names(glm::dvec2 a, glm::dvec2 b) const {
    double cost = 0.0;
    for (const Box& name : names_) cost += length_inside(a, b, grown(name, 1.0)) > 0.0 ? 1e6 : 0.0;
    for (const auto& [c, d] : name_leaders_) cost += segments_cross(a, b, c, d) ? 1e6 : 0.0;
    return cost;
  }

  double cost_of(const Box& box) const {
    const Box halo = grown(box, 0.8);
    double cost = 0.0;
    for (const auto& [a, b] : name_leaders_) cost += 1e4 * length_inside(a, b, halo);  // never hidden
    // A clearance of a third of the font size: LaTeX's fonts (TikZ) set a label a little wider than DejaVu.
    for (const PlacedText& other : page_.labels) cost += 1000.0 * overlap_area(grown(other.box, 0.3 * font_), box);
    for (const auto& [a, b] : lines_) cost += 4.0 * font_ * length_inside(a, b, halo);
    // A label's halo over a placed object's disc erases that part of it; over the grey backdrop of the
    // construction frames it hides nothing that matters.
    const double disc_weight = page_.objects_faded ? 1.0 : kOverObjectWeight;
    for (const PageDisc& disc : page_.discs) cost += disc_weight * disc_cover(disc, box);
    const Box& area = page_.area;
    cost += 1000.0 * (box.width() * box.height() - overlap_area(box, area));
    if (page_.inset.shown()) cost += 1000.0 * overlap_area(grown(page_.inset.box, 0.3 * font_), box);
    return cost;
  }

  PageFrame& page_;
  double font_;
  std::vector<std::pair<glm::dvec2, glm::dvec2>> lines_;    // everything drawn: rays cost, the rest forbids
  std::vector<std::pair<glm::dvec2, glm::dvec2>> solid_;    // the camera, the ticks, the crosses, the leaders
  std::vector<std::pair<glm::dvec2, glm::dvec2>> leaders_;       // every label's
  std::vector<std::pair<glm::dvec2, glm::dvec2>> name_leaders_;  // the names'
  std::vector<Box> names_;  // the objects' names placed in the drawing
};

struct Name {
  std::size_t object, disc;
  std::string markup;
};

// The objects' names, the most hemmed in first: by the object; then, for those with no such place, on a
// leader; the objects left over are returned (for the key).
std::vector<std::size_t> place_names(const std::vector<Name>& names, Placer& placer) {
  std::vector<std::pair<std::size_t, const Name*>> order;
  for (const Name& name : names) order.push_back({placer.places_by(name.markup, name.disc).size(), &name});
  std::stable_sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<const Name*> away;
  for (const auto& [count, name] : order) {
    const std::vector<PlacedText> places = placer.places_by(name->markup, name->disc);
    if (places.empty())
      away.push_back(name);
    else
      placer.add(places.front());
  }
  std::vector<std::size_t> left;
  for (const Name* name : away)
    if (!placer.place_on_leader(name->markup, name->disc)) left.push_back(name->object);
  return left;
}

// Places the labels; returns the objects whose names found no place in the drawing.
std::vector<std::size_t> place_labels(const Frame& frame, PageFrame& page, double font, const std::vector<int>& drawn,
                                      const std::vector<bool>& keyed) {
  Placer placer(page, font);
  for (const Marker& m : frame.markers)  // the points first: they matter most
    if (!m.label.empty() && inside(page.area, page.to_page(m.at))) placer.place({m.label, page.to_page(m.at), true});
  // Then the names, which have the fewest places (by their own object), before the free labels.
  std::vector<Name> names;
  if (!frame.objects_faded && frame.objects.size() <= kObjectNamesUpTo)
    for (std::size_t i = 0; i < frame.objects.size(); ++i) {
      if (frame.objects[i].name.empty() || drawn[i] < 0 || keyed[i]) continue;
      const PageDisc& disc = page.discs[std::size_t(drawn[i])];
      if (box_to_point(page.area, disc.centre) >= disc.radius) continue;  // in the margin kept, out of view
      names.push_back({i, std::size_t(drawn[i]), escape_markup(frame.objects[i].name)});
    }
  std::vector<std::size_t> left = place_names(names, placer);
  for (const Label& l : frame.labels)
    if (inside(page.area, page.to_page(l.at))) placer.place({l.text, page.to_page(l.at), false});
  // A free label that found no other place than over a name: the name moves, around the free labels.
  for (const Name& name : names) {
    if (std::find(left.begin(), left.end(), name.object) != left.end()) continue;
    if (placer.still_free(name.markup, name.disc)) continue;
    const std::vector<PlacedText> places = placer.places_by(name.markup, name.disc);
    if (!places.empty())
      placer.add(places.front());
    else if (!placer.place_on_leader(name.markup, name.disc))
      left.push_back(name.object);
  }
  std::sort(left.begin(), left.end());
  return left;
}

// ---- the matrix -----------------------------------------------------------------------------------------

void lay_out_matrix(const Frame& frame, const Bands& bands, Language language, PageFrame& page) {
  const int n = frame.matrix_size;
  std::vector<std::string> cells;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) cells.push_back("$" + matrix_entry(frame.matrix[std::size_t(r)][std::size_t(c)], language) + "$");
  std::vector<double> widths(std::size_t(n), 0.0);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c)
      widths[std::size_t(c)] = std::max(widths[std::size_t(c)], measure_text(cells[std::size_t(r * n + c)], bands.font).width);
  const std::string name = "$M_d =$";
  const double top = bands.matrix_top;
  const double middle = top + 0.5 * n * bands.line;
  const PlacedText name_text = text_at(name, {bands.area.left, middle + 0.35 * bands.font}, bands.font, false);
  page.matrix_name = name_text;
  const double bracket = 0.4 * bands.font, column_gap = 1.2 * bands.font;
  double x = name_text.box.right + 0.4 * bands.font + bracket;
  page.matrix_brackets.left = x - bracket;
  page.matrix_brackets.top = top;
  page.matrix_brackets.bottom = top + n * bands.line;
  for (int c = 0; c < n; ++c) {
    x += (c == 0 ? 0.0 : column_gap) + widths[std::size_t(c)];
    for (int r = 0; r < n; ++r)
      page.cells.push_back({cells[std::size_t(r * n + c)], x, top + (r + 0.78) * bands.line});
  }
  page.matrix_brackets.right = x + bracket;
  // Row by row, as a reader (and pdftotext) reads them.
  std::stable_sort(page.cells.begin(), page.cells.end(),
                   [](const MatrixCell& a, const MatrixCell& b) { return a.baseline < b.baseline; });
}

}  // namespace

double overlap_area(const Box& a, const Box& b) {
  const double w = std::min(a.right, b.right) - std::max(a.left, b.left);
  const double h = std::min(a.bottom, b.bottom) - std::max(a.top, b.top);
  return w > 0.0 && h > 0.0 ? w * h : 0.0;
}

int PageSize::width_px() const { return std::max(1, int(std::lround(width_pt * pixels_per_point))); }
int PageSize::height_px() const { return std::max(1, int(std::lround(height_pt * pixels_per_point))); }

PageSize page_in_mm(double width, double height, double dpi) {
  return {width * kPointsPerMm, height * kPointsPerMm, dpi / 72.0};
}

PageSize page_in_px(int width, int height) { return {0.75 * width, 0.75 * height, 1.0 / 0.75}; }

TextExtent measure_text(const std::string& markup, double size, bool bold) {
  TextExtent e;
  for (const TextRun& run : parse_math_text(markup)) {
    const double run_size = run.level == 0 ? size : kScriptScale * size;
    const double shift = run.level < 0 ? kSubscriptDrop * size : run.level > 0 ? -kSuperscriptRise * size : 0.0;
    // The ink, and the font's ascent and descent: a PDF reader boxes a word by them.
    const RunMetrics x = measure_run(run.text, run_size, bold);
    e.width += x.x_advance;
    double above = std::max(-x.y_bearing, x.ascent) - shift;
    if (run.vector) above = std::max(above, 0.72 * size + 0.3 * size - shift);  // the arrow over it
    e.above = std::max(e.above, above);
    e.below = std::max(e.below, std::max(x.height + x.y_bearing, x.descent) + shift);
  }
  return e;
}

double room_for_drawing_pt(const Figure& figure, const FigureOutput& output) {
  return bands_of(figure, output).room;
}

namespace {

// The drawing of a frame in `area`: its objects, lines, points, inset and labels, the names of the objects
// `keyed` left out; `left` gets the objects whose names found no place.
PageFrame drawing_of(const Frame& frame, const Box& area, double font, const std::vector<bool>& keyed,
                     std::vector<std::size_t>& left) {
  PageFrame page;
  page.area = area;
  page.font_size = font;
  page.arm = 0.35 * font;
  page.to_page = transform_of(frame, area);
  page.objects_faded = frame.objects_faded;
  const std::vector<int> drawn = add_discs(frame, page);
  add_segments(frame, page.to_page, page);
  const Box kept = grown(page.area, 20.0);
  for (const Marker& m : frame.markers)  // a point far out of view is left out (its label too)
    if (inside(kept, page.to_page(m.at))) page.markers.push_back({m.point, page.to_page(m.at)});
  add_inset(frame, page);
  left = place_labels(frame, page, font, drawn, keyed);
  return page;
}

// The names that found no place in the drawing go to a key in a column at the drawing's right, which the
// drawing gives up; the layout is made again until every name is in the drawing or in the key.
PageFrame drawing_with_key(const Frame& frame, const Box& area, double font) {
  std::vector<bool> keyed(frame.objects.size(), false);
  std::vector<std::size_t> left;
  PageFrame page = drawing_of(frame, area, font, keyed, left);
  while (!left.empty()) {
    for (std::size_t i : left) keyed[i] = true;
    const double swatch = 0.35 * font;
    double widest = 0.0, line = kLineSpacing * font;
    std::vector<std::size_t> entries;
    for (std::size_t i = 0; i < frame.objects.size(); ++i)
      if (keyed[i]) {
        entries.push_back(i);
        const TextExtent e = measure_text(escape_markup(frame.objects[i].name), font);
        widest = std::max(widest, e.width);
        line = std::max(line, e.above + e.below + 0.1 * font);  // the font's whole height: no two entries touch
      }
    const double width = 0.5 * font + 2.0 * swatch + 0.4 * font + widest;
    Box narrowed = area;
    narrowed.right -= width;
    // A drawing narrowed below half, or a key taller than the drawing: no room for the names.
    const bool room = narrowed.width() >= 0.5 * area.width() && entries.size() * line <= area.height();
    if (!room) {
      page.names_fit = false;
      return page;
    }
    page = drawing_of(frame, narrowed, font, keyed, left);
    double baseline = area.top + font;  // below the top by about the font's ascent
    for (std::size_t i : entries) {
      KeyEntry entry;
      entry.colour = frame.objects[i].colour;
      entry.swatch_radius = swatch;
      const double x = narrowed.right + 0.5 * font;
      entry.swatch = {x + swatch, baseline - 0.35 * font};
      const glm::dvec2 at(x + 2.0 * swatch + 0.4 * font, baseline);
      entry.text = text_at(escape_markup(frame.objects[i].name), at, font, false);
      page.key.push_back(entry);
      baseline += line;
    }
  }
  return page;
}

}  // namespace

PageFrame lay_out_frame(const Figure& figure, int index, const FigureOutput& output) {
  const Frame& frame = figure.frames[std::size_t(index)];
  const Bands bands = bands_of(figure, output);
  PageFrame page = drawing_with_key(frame, bands.area, bands.font);

  if (output.title)
    page.title = (text_at(frame.title, {bands.margin, bands.margin + kTitleScale * bands.font},
                                 kTitleScale * bands.font, true));
  if (output.caption) {
    double y = bands.caption_top + 1.1 * bands.font;
    for (const std::string& line : wrap(frame.caption, bands.area.width(), bands.font)) {
      page.caption.push_back(text_at(line, {bands.margin, y}, bands.font, false));
      y += kCaptionSpacing * bands.font;
    }
  }
  if (output.matrix) lay_out_matrix(frame, bands, figure.language, page);
  return page;
}

bool names_fit(const Figure& figure, const std::vector<int>& frames, const FigureOutput& output) {
  for (int index : frames)  // only the placed frames name their objects
    if (!figure.frames[std::size_t(index)].objects_faded && !lay_out_frame(figure, index, output).names_fit)
      return false;
  return true;
}

PageSize smallest_page_for_names(const Figure& figure, const std::vector<int>& frames, const FigureOutput& output,
                                 double unit_pt, double largest_width_pt) {
  const double ratio = output.page.height_pt / output.page.width_pt;
  FigureOutput bigger = output;
  // Whole units (the size the user types), 1 % at a time beyond a hundred.
  for (double units = std::floor(output.page.width_pt / unit_pt + 1e-9) + 1.0; units * unit_pt <= largest_width_pt;
       units += std::max(1.0, std::floor(0.01 * units))) {
    bigger.page.width_pt = units * unit_pt;
    bigger.page.height_pt = std::ceil(units * ratio - 1e-9) * unit_pt;
    if (room_for_drawing_pt(figure, bigger) >= kLeastDrawingShare * bigger.page.height_pt &&
        names_fit(figure, frames, bigger))
      return bigger.page;
  }
  return output.page;
}

}  // namespace raycam::figure

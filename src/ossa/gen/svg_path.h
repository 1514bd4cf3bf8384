#pragma once
// SVG path data for the exporters (export_svg.cpp, svg_bone_shapes.cpp): numbers written
// compactly, a bounds accumulator and PathBuilder, which writes path data in a bone's local
// frame and keeps the points it wrote (for the drawing's bounds). Internal to ossa::core's
// SVG export; not part of the public interface.

#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec2.hpp>

namespace ossa::svg {

// Shortest round-trip-ish text of a finite float ("%.5g" keeps five significant digits, enough
// for a drawing at any scale; SVG accepts the exponent form).
inline void append_num(std::string& out, float v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.5g", static_cast<double>(v));
  out += buf;
}

inline std::string num(float v) {
  std::string s;
  append_num(s, v);
  return s;
}

struct Bounds {
  glm::vec2 lo{std::numeric_limits<float>::max()};
  glm::vec2 hi{std::numeric_limits<float>::lowest()};
  void add(glm::vec2 p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  bool empty() const { return lo.x > hi.x; }
};

// Builds path data. `flip` rotates the shape by 180° about (flip_len / 2, 0): a shape authored
// for a headward bone (+x to the head, +y dorsal) then fits a tailward one.
class PathBuilder {
 public:
  explicit PathBuilder(bool flip = false, float flip_len = 0.0f) : flip_(flip), len_(flip_len) {}

  void move(glm::vec2 p) { cmd('M', {p}); }
  void line(glm::vec2 p) { cmd('L', {p}); }
  void quad(glm::vec2 c, glm::vec2 p) { cmd('Q', {c, p}); }
  void cubic(glm::vec2 c1, glm::vec2 c2, glm::vec2 p) { cmd('C', {c1, c2, p}); }
  // Circular arc of radius r about `center` to p (the center only feeds the bounds).
  void arc(float r, bool large, bool sweep, glm::vec2 p, glm::vec2 center) {
    d_ += 'A';
    append_num(d_, r);
    d_ += ' ';
    append_num(d_, r);
    d_ += large ? " 0 1 " : " 0 0 ";
    d_ += sweep ? "1 " : "0 ";
    point(p);
    const glm::vec2 c = map(center);
    points_.push_back(c + glm::vec2(r, r));
    points_.push_back(c - glm::vec2(r, r));
  }
  void close() { d_ += "Z"; }

  // Closed shapes.
  void circle(glm::vec2 c, float r) {
    move(c + glm::vec2(r, 0.0f));
    arc(r, true, true, c - glm::vec2(r, 0.0f), c);
    arc(r, true, true, c + glm::vec2(r, 0.0f), c);
    close();
  }
  // A tapered capsule from a (radius ra) to b (radius rb).
  void capsule(glm::vec2 a, glm::vec2 b, float ra, float rb) {
    glm::vec2 dir = b - a;
    const float len = std::sqrt(dir.x * dir.x + dir.y * dir.y);
    dir = len > 1e-12f ? dir / len : glm::vec2(1.0f, 0.0f);
    const glm::vec2 n(-dir.y, dir.x);
    move(a + n * ra);
    line(b + n * rb);
    arc(rb, false, false, b - n * rb, b);
    line(a - n * ra);
    arc(ra, false, false, a + n * ra, a);
    close();
  }
  void polygon(std::initializer_list<glm::vec2> pts) {
    bool first = true;
    for (glm::vec2 p : pts) {
      if (first) move(p); else line(p);
      first = false;
    }
    close();
  }

  const std::string& data() const { return d_; }
  const std::vector<glm::vec2>& points() const { return points_; }
  bool empty() const { return d_.empty(); }

 private:
  glm::vec2 map(glm::vec2 p) const { return flip_ ? glm::vec2(len_ - p.x, -p.y) : p; }
  void point(glm::vec2 p) {
    p = map(p);
    append_num(d_, p.x);
    d_ += ' ';
    append_num(d_, p.y);
    points_.push_back(p);
  }
  void cmd(char c, std::initializer_list<glm::vec2> pts) {
    d_ += c;
    bool first = true;
    for (glm::vec2 p : pts) {
      if (!first) d_ += ' ';
      point(p);
      first = false;
    }
  }

  bool flip_;
  float len_;
  std::string d_;
  std::vector<glm::vec2> points_;
};

}  // namespace ossa::svg

// Tests of the SVG and OBJ exporters (src/ossa/gen/export_svg.h, export_obj.h) on hand-built
// creatures (scenes::hand_built_creature, tests/shared/hand_creature.cpp), and — when the
// example dataset and generator are available — on all 44 examples.

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <regex>
#include <sstream>
#include <string>

#include "ossa/body/body_mesh.h"
#include "ossa/gen/export_obj.h"
#include "ossa/gen/export_svg.h"
#include "ossa/gen/generator.h"
#include "ossa/gen/skeleton_builder.h"
#include "shared/scenes.h"
#include "tools/xml_check.h"

namespace ossa {
namespace {

int count_of(const std::string& text, const std::string& needle) {
  int n = 0;
  for (size_t p = text.find(needle); p != std::string::npos; p = text.find(needle, p + 1)) ++n;
  return n;
}

int drawn_bones(const Creature& c) {
  int n = 0;
  for (int i = 0; i < c.skeleton.bone_count(); ++i) n += c.skeleton.length(i) > 0.0f;
  return n;
}

// viewBox="x y w h" of the outermost <svg>.
std::array<float, 4> view_box(const std::string& svg) {
  std::smatch m;
  const std::regex re("viewBox=\"([^\"]*)\"");
  REQUIRE(std::regex_search(svg, m, re));
  std::istringstream in(m[1].str());
  std::array<float, 4> v{};
  in >> v[0] >> v[1] >> v[2] >> v[3];
  return v;
}

}  // namespace

TEST_CASE("xml checker accepts well-formed and rejects broken documents", "[gen][svg]") {
  CHECK(test::xml_error("<a x=\"1\"><b/>t &amp; u</a>").empty());
  CHECK(test::xml_error("<?xml version=\"1.0\"?>\n<a><!-- c --></a>\n").empty());
  CHECK_FALSE(test::xml_error("<a><b></a></b>").empty());
  CHECK_FALSE(test::xml_error("<a>x & y</a>").empty());
  CHECK_FALSE(test::xml_error("<a x=\"<\"/>").empty());
  CHECK_FALSE(test::xml_error("<a x=1/>").empty());
  CHECK_FALSE(test::xml_error("<a x=\"1\" x=\"2\"/>").empty());
  CHECK_FALSE(test::xml_error("<a/><b/>").empty());
  CHECK_FALSE(test::xml_error("<a>").empty());
}

TEST_CASE("hand-built creature stands on the ground", "[gen][svg]") {
  for (bool winged : {false, true}) {
    const Creature c = scenes::hand_built_creature(winged);
    REQUIRE(c.skeleton.is_valid());
    const std::vector<Mat2x3> m = model_matrices(c.skeleton, c.rest_pose.locals);
    for (const Limb& limb : c.limbs) {
      if (limb.kind != LimbKind::kLeg) continue;
      const float y = bone_end(m[limb.bones[2]], c.skeleton.length(limb.bones[2])).y;
      CHECK(y == Approx(0.0f).margin(0.08f));
    }
  }
}

TEST_CASE("creature SVG is well-formed, draws every bone and orders the layers", "[gen][svg]") {
  for (bool winged : {false, true}) {
    for (ContactMode contact : {ContactMode::kTip, ContactMode::kFlat}) {
      const Creature c = scenes::hand_built_creature(winged, contact);
      const std::string svg = creature_svg(c);
      INFO(c.name);
      CHECK(test::xml_error(svg).empty());
      CHECK(count_of(svg, "data-bone=") == drawn_bones(c));
      CHECK(count_of(svg, "nan") == 0);
      CHECK(count_of(svg, "inf") == 0);
      // Bones are shapes (paths), not lines: the only <line> is the ground.
      CHECK(count_of(svg, "<line") == 1);
      const size_t far = svg.find("class=\"far\""), body = svg.find("class=\"body\""),
                   near = svg.find("class=\"near\"");
      REQUIRE(far != std::string::npos);
      REQUIRE(body != std::string::npos);
      REQUIRE(near != std::string::npos);
      CHECK(far < body);
      CHECK(body < near);
      // The far side is darker than the near side.
      CHECK(svg.find("fill=\"#9c9382\"") < svg.find("fill=\"#e8dcc0\""));
    }
  }
}

TEST_CASE("creature SVG viewBox contains every joint and the ground", "[gen][svg]") {
  const Creature c = scenes::hand_built_creature();
  const std::array<float, 4> vb = view_box(creature_svg(c));
  const std::vector<Mat2x3> m = model_matrices(c.skeleton, c.rest_pose.locals);
  for (int i = 0; i < c.skeleton.bone_count(); ++i) {
    for (glm::vec2 p : {bone_start(m[i]), bone_end(m[i], c.skeleton.length(i))}) {
      // SVG y is the negated model y.
      CHECK(p.x >= vb[0]);
      CHECK(p.x <= vb[0] + vb[2]);
      CHECK(-p.y >= vb[1]);
      CHECK(-p.y <= vb[1] + vb[3]);
    }
  }
  CHECK(vb[1] + vb[3] > 0.0f);  // ground (y = 0) inside
}

TEST_CASE("creature SVG escapes names and survives non-finite bones", "[gen][svg]") {
  Creature c = scenes::hand_built_creature();
  c.name = "<tiger & \"cat\"> 'x'";
  BoneLocal bad;
  bad.offset_ls = {std::numeric_limits<float>::quiet_NaN(), 0.0f};
  c.skeleton.add_bone("bad <bone>", BoneKind::kTailVertebra, c.tail.back(), 0.1f, 0.02f, bad,
                      Layer::kBody);
  c.skeleton.add_bone("inf", BoneKind::kRib, c.root, std::numeric_limits<float>::infinity(),
                      0.02f, {}, Layer::kNear);
  c.rest_pose = Pose::rest(c.skeleton);
  const std::string svg = creature_svg(c);
  CHECK(test::xml_error(svg).empty());
  CHECK(svg.find("&lt;tiger &amp; &quot;cat&quot;&gt; &apos;x&apos;") != std::string::npos);
  CHECK(count_of(svg, "nan") == 0);
  CHECK(count_of(svg, "inf") == 0);
  for (int variant = -1; variant < 4; ++variant) {
    SvgOptions o;
    o.skull_variant = variant;
    CHECK(test::xml_error(creature_svg(c, o)).empty());
  }
}

TEST_CASE("sheet SVG is well-formed with one cell and one label per creature", "[gen][svg]") {
  std::vector<std::pair<std::string, Creature>> list;
  list.emplace_back("Pferd & <horse>", scenes::hand_built_creature(false));
  list.emplace_back("bird", scenes::hand_built_creature(true));
  list.emplace_back("flat (Fu\xc3\x9f & <x>)", scenes::hand_built_creature(false, ContactMode::kFlat));
  const std::string svg = sheet_svg(list, 2);
  CHECK(test::xml_error(svg).empty());
  CHECK(count_of(svg, "<svg") == 4);
  CHECK(count_of(svg, "<text") == 3);
  CHECK(count_of(svg, "<tspan") == 1);
  CHECK(svg.find("(Fu\xc3\x9f &amp; &lt;x&gt;)") != std::string::npos);
  CHECK(svg.find("Pferd &amp; &lt;horse&gt;") != std::string::npos);
  CHECK(test::xml_error(sheet_svg({}, 0)).empty());
}

TEST_CASE("OBJ proxies: one box per bone with 8 vertices and 6 faces", "[gen][obj]") {
  for (bool winged : {false, true}) {
    const Creature c = scenes::hand_built_creature(winged);
    const std::string obj = creature_obj(c);
    const int boxes = drawn_bones(c);
    CHECK(creature_obj_box_count(c) == boxes);
    std::istringstream in(obj);
    std::string line;
    int v = 0, f = 0, o = 0, g = 0;
    int max_index = 0;
    std::vector<std::string> names;
    std::string current;
    float near_z_min = 1e9f, far_z_max = -1e9f;
    while (std::getline(in, line)) {
      std::istringstream ls(line);
      std::string tag;
      ls >> tag;
      if (tag == "v") {
        float x, y, z;
        ls >> x >> y >> z;
        REQUIRE(std::isfinite(x));
        REQUIRE(std::isfinite(y));
        REQUIRE(std::isfinite(z));
        if (current.find("_near") != std::string::npos) near_z_min = std::min(near_z_min, z);
        if (current.find("_far") != std::string::npos) far_z_max = std::max(far_z_max, z);
        ++v;
      } else if (tag == "f") {
        int idx, count = 0;
        while (ls >> idx) {
          CHECK(idx >= 1);
          max_index = std::max(max_index, idx);
          ++count;
        }
        CHECK(count == 4);
        ++f;
      } else if (tag == "o") {
        ls >> current;
        names.push_back(current);
        ++o;
      } else if (tag == "g") {
        ++g;
      }
    }
    CHECK(v == 8 * boxes);
    CHECK(f == 6 * boxes);
    CHECK(o == boxes);
    CHECK(g == boxes);
    CHECK(max_index == v);
    for (int i = 0; i < c.skeleton.bone_count(); ++i) {
      if (c.skeleton.length(i) > 0.0f) {
        CHECK(std::find(names.begin(), names.end(), c.skeleton.name(i)) != names.end());
      }
    }
    // Near copies in front of the body plane, far copies behind it.
    CHECK(near_z_min > 0.0f);
    CHECK(far_z_max < 0.0f);
  }
}

TEST_CASE("every example's SVG is valid XML and draws every bone", "[gen][svg]") {
  Result<Generator> gen = Generator::load(scenes::source_path("assets/creatures/examples.json"), ossa::body_volume_m3);
  REQUIRE(gen.ok());
  REQUIRE(gen->dataset().animals.size() == 44);
  std::vector<std::pair<std::string, Creature>> sheet;
  for (const Animal& animal : gen->dataset().animals) {
    INFO(animal.name);
    Result<Genome> genome = gen->example(animal.name, 1);
    REQUIRE(genome.ok());
    Result<Creature> c = build_creature(*genome);
    REQUIRE(c.ok());
    SvgOptions o;
    o.skull_variant = genome->skull_variant;
    const std::string svg = creature_svg(*c, o);
    CHECK(test::xml_error(svg).empty());
    CHECK(count_of(svg, "data-bone=") == drawn_bones(*c));
    CHECK(count_of(svg, "nan") == 0);
    CHECK(count_of(svg, "inf") == 0);
    sheet.emplace_back(animal.name + " (" + animal.name_de + ")", std::move(*c));
  }
  const std::string svg = sheet_svg(sheet, 6);
  CHECK(test::xml_error(svg).empty());
  CHECK(count_of(svg, "<svg") == 45);
}

TEST_CASE("random creatures export valid SVG and OBJ", "[gen][svg][obj]") {
  Result<Generator> gen = Generator::load(scenes::source_path("assets/creatures/examples.json"), ossa::body_volume_m3);
  REQUIRE(gen.ok());
  for (uint64_t seed = 1; seed <= 150; ++seed) {
    GenerateOptions options;
    options.genome.multi_limb = seed % 3 == 0;
    options.genome.neck_girdle = seed % 5 == 0;
    Result<Creature> c = build_creature(gen->random(seed, options));
    INFO("seed " << seed);
    REQUIRE(c.ok());
    const std::string svg = creature_svg(*c);
    CHECK(test::xml_error(svg).empty());
    CHECK(count_of(svg, "nan") == 0);
    const std::string obj = creature_obj(*c);
    CHECK(count_of(obj, "\nv ") == 8 * creature_obj_box_count(*c));
    CHECK(count_of(obj, "\nf ") == 6 * creature_obj_box_count(*c));
  }
}

}  // namespace ossa

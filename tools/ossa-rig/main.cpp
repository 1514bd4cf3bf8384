// ossa-rig — rig mappings of skinned characters made in other tools (anim/rig_mapping.h,
// anim/character.h): a starting mapping guessed from bone names, and a check of a mapping
// against its mesh with the character standing on flat ground.
//
//   ossa-rig guess MESH [--out F.rig.json]   the mapping as JSON (stdout, or F written atomically)
//   ossa-rig check F.rig.json                 JSON: bones, legs, arms, reach, hip height, problems
//
// Every failure prints one line naming the file, the field and the bone, and exits with
// status 1 (2 for a bad command line).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "ossa/anim/animator.h"
#include "ossa/rig/rig_guess.h"
#include "ossa/rig/rig_mapping.h"
#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "ossa/level/level.h"
#include "ossa/render/character_mesh.h"

using namespace ossa;

namespace {

const char* kUsage = R"(usage: ossa-rig guess MESH [--out F.rig.json]
       ossa-rig check F.rig.json
  guess   a starting rig mapping from the mesh's bone names (Rigify thigh.L, Mixamo
          mixamorig:LeftUpLeg, Unreal thigh_l, plain left_leg_upper ...; case and separators
          do not matter): JSON on stdout, or written to --out (atomically; "mesh" relative to it).
          Notes on what was not found go to stderr.
  check   loads the mapping and its mesh, builds the character, stands it on flat ground and
          prints JSON: bones, legs (reach, hip height, knee direction), arms, the character's
          hip height, walk and run speeds, where each foot stands, and rest-pose problems.
MESH is a glTF 2.0 (.gltf, .glb), FBX or DAE file with a skinned mesh.
)";

[[noreturn]] void fail(const std::string& message, int code = 1) {
  std::fprintf(stderr, "ossa-rig: %s\n", message.c_str());
  std::exit(code);
}

int guess(const std::string& mesh_path, const std::string& out, bool out_given) {
  Result<RiggedMesh> mesh = load_rigged_mesh(mesh_path);
  if (!mesh) fail(mesh.message());
  // Never over the mesh or a file it names (io/file.h).
  if (out_given) {
    std::vector<std::string> inputs = mesh->files;
    inputs.push_back(mesh_path);
    if (Status s = check_output_path("--out", out, inputs); !s) fail(s.message());
  }
  namespace fs = std::filesystem;
  std::string mesh_field = fs::path(mesh_path).filename().string();
  if (out_given && !out.empty()) {
    const fs::path base = fs::absolute(fs::path(out)).parent_path();
    mesh_field = fs::absolute(fs::path(mesh_path)).lexically_relative(base).generic_string();
  }
  const RigGuess g = guess_rig_mapping(imported_skeleton(*mesh), mesh_field);
  for (const std::string& note : g.notes) std::fprintf(stderr, "ossa-rig: note: %s\n", note.c_str());
  const Json doc = rig_mapping_to_json(g.mapping);
  if (!out_given) {
    std::fputs(json_file_text(doc).c_str(), stdout);
  } else {
    if (Status s = write_json_atomic(out, doc); !s) fail(s.message());
    std::printf("wrote %s: %zu legs, %zu arms, root %s\n", out.c_str(), g.mapping.legs.size(), g.mapping.arms.size(),
                g.mapping.root.c_str());
  }
  return 0;
}

int check(const std::string& rig_path) {
  Result<LoadedCharacter> loaded = load_character(rig_path);
  if (!loaded) fail(loaded.message());
  const Character& c = *loaded->character;
  const AnimRig& rig = *c.rig;
  // Stand it on flat ground for a second.
  const Level flat({Box::from_corner(-50.0f, -1.0f, 100.0f, 1.0f)});
  Animator a(c.rig, SplinePrototypes::defaults());
  a.reset({0.0f, 0.0f}, flat);
  for (int i = 0; i < 120; ++i) a.update(1.0f / 120.0f, 0.0f, flat);
  std::vector<std::string> problems = c.warnings;
  float low = 1e30f, high = -1e30f;
  for (int i = 0; i < a.leg_count(); ++i) {
    const float y = a.foot_ws(i).y;
    low = std::min(low, y);
    high = std::max(high, y);
    if (std::fabs(y) > 0.005f) {
      char what[160];
      std::snprintf(what, sizeof what, "legs[%d] (%s) does not reach the ground standing: its contact point is %.3f m off it", i,
                    c.mapping.legs[static_cast<size_t>(i)].end.c_str(), y);
      problems.push_back(what);
    }
  }
  for (size_t g = 0; g < rig.girdles.size(); ++g) {
    const RigGirdle& girdle = rig.girdles[g];
    for (size_t k = 1; k < girdle.legs.size(); ++k) {
      const RigLeg& first = rig.legs[static_cast<size_t>(girdle.legs[0])];
      const RigLeg& other = rig.legs[static_cast<size_t>(girdle.legs[k])];
      const float d = glm::length(bone_start(rig.model_rest[static_cast<size_t>(other.bones[0])]) -
                                  bone_start(rig.model_rest[static_cast<size_t>(first.bones[0])]));
      if (d > 0.01f * first.reach) {
        char what[200];
        std::snprintf(what, sizeof what, "legs %d and %d share a girdle but their hips are %.3f m apart: the animator measures "
                      "both from the first, so the second may slide (give both one hip joint in the side view)",
                      girdle.legs[0], girdle.legs[k], d);
        problems.push_back(what);
      }
    }
  }
  Json legs = Json::array();
  float reach = 0.0f;
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    const RigLeg& leg = rig.legs[i];
    const RigChain& m = c.mapping.legs[i];
    reach = std::max(reach, leg.reach);
    legs.push_back({{"upper", m.upper}, {"lower", m.lower}, {"foot", m.end}, {"side", m.side == Side::kFar ? "far" : "near"},
                    {"pair", c.mapping.leg_pair(i)}, {"knee", leg.bend > 0.0f ? "forward" : "back"},
                    {"reach_m", json_float(leg.reach)}, {"foot_m", json_float(leg.foot_span)},
                    {"hip_height_m", json_float(rig.girdles[static_cast<size_t>(leg.girdle)].rest_height)},
                    {"contact_ms", {json_float(c.contacts_ms[i].x), json_float(c.contacts_ms[i].y)}},
                    {"standing_foot_y_m", json_float(a.foot_ws(static_cast<int>(i)).y)}});
  }
  Json arms = Json::array();
  for (size_t i = 0; i < rig.arms.size(); ++i) {
    const RigLimb& arm = rig.arms[i];
    const RigChain& m = c.mapping.arms[i];
    float len = 0.0f;
    for (int b : arm.bones) len += rig.skeleton.length(b);
    arms.push_back({{"upper", m.upper}, {"lower", m.lower}, {"hand", m.end}, {"side", m.side == Side::kFar ? "far" : "near"},
                    {"length_m", json_float(len)}});
  }
  Json out = {{"character", c.name},
              {"mapping", rig_path},
              {"mesh", c.mapping.mesh_path},
              {"bones", rig.skeleton.bone_count()},
              {"legs", legs},
              {"leg_pairs", rig.girdles.size()},
              {"arms", arms},
              {"tail_bones", rig.tail.size()},
              {"head", c.mapping.head},
              {"leg_reach_m", json_float(reach)},
              {"hip_height_m", json_float(rig.hip_height)},
              {"walk_speed_m_s", json_float(a.walk_speed())},
              {"run_speed_m_s", json_float(a.run_speed())},
              {"standing", {{"lowest_foot_m", json_float(low)}, {"highest_foot_m", json_float(high)}}},
              {"problems", problems}};
  std::printf("%s\n", json_text(out, 2).c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty()) fail("missing command (see --help)", 2);
    if (args[0] == "--help" || args[0] == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (args[0] == "guess") {
      std::string mesh, out;
      bool out_given = false;
      for (size_t i = 1; i < args.size(); ++i) {
        if (args[i] == "--out") {
          if (i + 1 >= args.size()) fail("--out: missing value", 2);
          out = args[++i];
          out_given = true;
        } else if (!args[i].empty() && args[i][0] == '-') {
          fail("unknown option " + args[i] + " (see --help)", 2);
        } else if (mesh.empty()) {
          mesh = args[i];
        } else {
          fail("guess takes one mesh, got also \"" + args[i] + "\"", 2);
        }
      }
      if (mesh.empty()) fail("guess: missing MESH", 2);
      return guess(mesh, out, out_given);
    }
    if (args[0] == "check") {
      if (args.size() != 2 || args[1].empty() || args[1][0] == '-') fail("check takes one rig mapping (F.rig.json)", 2);
      return check(args[1]);
    }
    fail("unknown command \"" + args[0] + "\" (expected guess or check; see --help)", 2);
  } catch (const std::exception& e) {
    fail(std::string("unexpected error: ") + e.what());
  }
}

// EditorSuite: the Rig window (rig_editor_model.h) — open a skinned mesh or a rig mapping, see
// the mesh's bone tree with the part each bone plays, pick a part and click a bone to give it
// that part (a leg is three clicks: upper, lower, foot), guess from the bone names, and watch
// the character it builds stand, walk or run on flat ground; save atomically, apply to the
// player. Every edit is one undo step (Ctrl+Z).
#include <algorithm>
#include <cstdio>
#include <string>

#include "ossa/editor/editor_suite.h"
#include "ossa/editor/editor_suite_internal.h"
#include "ossa/render/character_mesh.h"
#include "ossa/skeleton/pose.h"

namespace ossa {

namespace {

const char* slot_label(RigSlotKind k) {
  switch (k) {
    case RigSlotKind::kRoot: return "root";
    case RigSlotKind::kSpine: return "spine";
    case RigSlotKind::kNeck: return "neck";
    case RigSlotKind::kHead: return "head";
    case RigSlotKind::kTail: return "tail";
    case RigSlotKind::kLegUpper:
    case RigSlotKind::kArmUpper: return "upper";
    case RigSlotKind::kLegLower:
    case RigSlotKind::kArmLower: return "lower";
    case RigSlotKind::kLegFoot: return "foot";
    case RigSlotKind::kArmHand: return "hand";
  }
  return "";
}

// One part: a button showing its bone (highlighted when selected); right-click clears it.
void slot_button(RigEditorModel& m, RigSlot slot, const std::string& bone) {
  const bool selected = m.slot() == slot;
  if (selected) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.85f, 0.45f, 0.15f, 1.0f));
  const std::string label = std::string(slot_label(slot.kind)) + ": " + (bone.empty() ? "-" : bone) + "##" + rig_slot_field(slot);
  if (ImGui::SmallButton(label.c_str())) m.select(slot);
  if (ImGui::IsItemClicked(ImGuiMouseButton_Right)) m.clear(slot);
  if (selected) ImGui::PopStyleColor();
}

void list_slots(RigEditorModel& m, RigSlotKind kind, const std::vector<std::string>& names) {
  for (size_t i = 0; i < names.size(); ++i) {
    slot_button(m, {kind, static_cast<int>(i)}, names[i]);
    ImGui::SameLine();
  }
  slot_button(m, {kind, static_cast<int>(names.size())}, "");  // one more: appends
}

void bone_tree(RigEditorModel& m, int bone) {
  const ImportedBone& b = m.skeleton().bones[static_cast<size_t>(bone)];
  const std::string part = m.part_of(bone);
  const std::string label = b.name + (part.empty() ? "" : "   [" + part + "]");
  const bool leaf = m.children(bone).empty();
  ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_DefaultOpen | ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_SpanAvailWidth;
  if (leaf) flags |= ImGuiTreeNodeFlags_Leaf | ImGuiTreeNodeFlags_NoTreePushOnOpen;
  if (m.bone_of(m.slot()) == bone) flags |= ImGuiTreeNodeFlags_Selected;
  if (!part.empty()) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.55f, 0.85f, 1.0f, 1.0f));
  const bool open = ImGui::TreeNodeEx(reinterpret_cast<void*>(static_cast<intptr_t>(bone)), flags, "%s", label.c_str());
  if (!part.empty()) ImGui::PopStyleColor();
  // A click (not on the arrow) gives the bone the selected part.
  if (ImGui::IsItemClicked(ImGuiMouseButton_Left) && !ImGui::IsItemToggledOpen()) m.assign(m.slot(), bone);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("click: make %s %s", b.name.c_str(), rig_slot_field(m.slot()).c_str());
  if (open && !leaf) {
    for (int c : m.children(bone)) bone_tree(m, c);
    ImGui::TreePop();
  }
}

}  // namespace

// The character's bones standing or walking on flat ground, the selected part's bone in
// orange, the feet's contact points in green.
void EditorSuite::draw_rig_preview(float width, float height) {
  const RigEditorModel& m = *rig_;
  const ImVec2 o = ImGui::GetCursorScreenPos();
  const ImVec2 size(width, height);
  ImGui::Dummy(size);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(o, ImVec2(o.x + size.x, o.y + size.y), IM_COL32(28, 30, 36, 255));
  const Animator* a = m.preview();
  if (!a) {
    dl->AddText(ImVec2(o.x + 8, o.y + 8), IM_COL32(255, 120, 100, 255), "no character: see the error below");
    return;
  }
  const Skeleton& sk = a->rig().skeleton;
  const std::vector<Mat2x3>& w = a->world_matrices();
  const float h = std::max(a->hip_height(), 0.05f);
  const float k = 0.32f * size.y / h;  // two and a half hip heights fill the height
  const glm::vec2 centre(a->x(), 1.1f * h);
  auto px = [&](glm::vec2 p) { return ImVec2(o.x + 0.5f * size.x + (p.x - centre.x) * k, o.y + 0.5f * size.y - (p.y - centre.y) * k); };
  // Ground with marks every half metre, so walking shows.
  const float ground = px({0.0f, 0.0f}).y;
  dl->AddLine(ImVec2(o.x, ground), ImVec2(o.x + size.x, ground), IM_COL32(150, 120, 80, 255), 2.0f);
  const float half_w = 0.5f * size.x / k;
  for (float x = std::floor((centre.x - half_w) / 0.5f) * 0.5f; x < centre.x + half_w; x += 0.5f) {
    const ImVec2 p = px({x, 0.0f});
    dl->AddLine(p, ImVec2(p.x, p.y + 5.0f), IM_COL32(150, 120, 80, 255));
  }
  const int selected_mesh_bone = m.bone_of(m.slot());
  const Character* c = m.character().get();
  // The skinned mesh as the game draws it (skinned on the CPU, textured with the mesh's
  // texture through ImGui), the bones over it.
  if (c && m.mesh()) {
    if (rig_preview_key_ != c) {
      rig_preview_key_ = c;
      rig_preview_mesh_ = character_sprite_mesh(*c, *m.mesh());
      const RiggedMesh& mesh = *m.mesh();
      rig_preview_texture_.reset();
      if (!mesh.texture_rgba.empty()) {
        rig_preview_texture_ = Texture::from_image(Image{mesh.texture_width, mesh.texture_height, mesh.texture_rgba});
      }
    }
    const SpriteMesh& sm = rig_preview_mesh_;
    const size_t bones = std::min(sm.inverse_bind.size(), w.size());
    std::vector<Mat2x3> palette(bones);
    for (size_t b = 0; b < bones; ++b) palette[b] = w[b] * sm.inverse_bind[b];
    std::vector<ImVec2> skinned(sm.vertices.size());
    for (size_t i = 0; i < sm.vertices.size(); ++i) {
      const SpriteVertex& v = sm.vertices[i];
      glm::vec2 p(0.0f);
      for (size_t k = 0; k < 4; ++k) {
        if (v.weights[k] <= 0.0f || v.bones[k] >= bones) continue;
        p += v.weights[k] * palette[v.bones[k]].apply(v.position_ms);
      }
      skinned[i] = px(p);
    }
    const bool textured = rig_preview_texture_ && rig_preview_texture_->is_valid();
    // The texture's coordinates are GL's, as the texture was uploaded (texture.h).
    if (textured) dl->PushTextureID(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(rig_preview_texture_->id())));
    const ImVec2 white = ImGui::GetFontTexUvWhitePixel();
    for (size_t t = 0; t + 2 < sm.indices.size(); t += 3) {
      dl->PrimReserve(3, 3);
      for (size_t k = 0; k < 3; ++k) {
        const SpriteVertex& v = sm.vertices[sm.indices[t + k]];
        dl->PrimVtx(skinned[sm.indices[t + k]], textured ? ImVec2(v.uv.x, v.uv.y) : white,
                    textured ? IM_COL32_WHITE : IM_COL32(200, 195, 185, 255));
      }
    }
    if (textured) dl->PopTextureID();
  }
  for (int b = 0; b < sk.bone_count(); ++b) {
    const bool hot = c && c->mesh_bone[static_cast<size_t>(b)] == selected_mesh_bone;
    const ImU32 col = hot ? IM_COL32(255, 150, 40, 255)
                      : sk.layer(b) == Layer::kFar ? IM_COL32(150, 140, 120, 255)
                                                   : IM_COL32(235, 225, 200, 255);
    dl->AddLine(px(bone_start(w[static_cast<size_t>(b)])), px(bone_end(w[static_cast<size_t>(b)], sk.length(b))), col,
                hot ? 3.0f : 1.0f);
  }
  for (int i = 0; i < a->leg_count(); ++i) dl->AddCircleFilled(px(a->foot_ws(i)), 3.0f, IM_COL32(90, 220, 110, 255));
}

void EditorSuite::draw_rig_window() {
  RigEditorModel& m = *rig_;
  place_next_window(EditorWindow::kRig);
  const std::string title = std::string("Rig") + (m.dirty() ? " *" : "") + "###rig";
  if (!ImGui::Begin(title.c_str(), &show_rig)) {
    ImGui::End();
    return;
  }
  // Files.
  ImGui::SetNextItemWidth(-150);
  ImGui::InputText("##rigmesh", rig_mesh_buf_, sizeof rig_mesh_buf_);
  ImGui::SameLine();
  if (ImGui::Button("Open mesh")) {
    const std::string path = rig_mesh_buf_;
    confirm_discard(EditorDocument::kRig, [this, path] {
      if (rig_->open_mesh(path).ok()) copy_to_buffer(rig_path_buf_, sizeof rig_path_buf_, rig_->path());
    });
  }
  ImGui::SetNextItemWidth(-150);
  ImGui::InputText("##rigpath", rig_path_buf_, sizeof rig_path_buf_);
  ImGui::SameLine();
  if (ImGui::Button("Open mapping")) {
    const std::string path = rig_path_buf_;
    confirm_discard(EditorDocument::kRig, [this, path] {
      if (rig_->open_mapping(path).ok()) copy_to_buffer(rig_mesh_buf_, sizeof rig_mesh_buf_, rig_->mapping().mesh_path);
    });
  }
  if (ImGui::Button("Save")) (void)m.save();
  ImGui::SameLine();
  if (ImGui::Button("Save as")) (void)m.save_as(rig_path_buf_);
  ImGui::SameLine();
  if (ImGui::Button("Save and apply to player") && m.is_open()) {
    Status s = m.dirty() || m.path() != rig_path_buf_ ? m.save_as(rig_path_buf_) : Status{};
    if (s.ok()) s = apply_character_to_player(m.path());
    character_message_ = s.ok() ? "the player is " + character_name(m.path()) : s.message();
  }
  show_messages(m.last_error(), m.is_open() ? m.path() : "open a skinned mesh (glTF, FBX, DAE) or a .rig.json");
  if (!m.is_open()) {
    ImGui::End();
    return;
  }

  // The result first: it is what the clicks change.
  static const char* kPace[] = {"stand", "walk", "run"};
  int pace = m.preview_stick >= 0.99f ? 2 : m.preview_stick > 0.0f ? 1 : 0;
  for (int i = 0; i < 3; ++i) {
    if (i) ImGui::SameLine();
    if (ImGui::RadioButton(kPace[i], pace == i)) m.preview_stick = i == 0 ? 0.0f : i == 1 ? 0.5f : 1.0f;
  }
  draw_rig_preview(ImGui::GetContentRegionAvail().x, 170.0f);
  if (const auto c = m.character()) {
    const AnimRig& rig = *c->rig;
    ImGui::Text("%s: %zu legs in %zu pairs, %zu arms, hip %.2f m", c->name.c_str(), rig.legs.size(), rig.girdles.size(),
                rig.arms.size(), rig.hip_height);
    for (const std::string& w : c->warnings) ImGui::TextDisabled("note: %s", w.c_str());
  }
  show_messages(m.error(), "");
  for (const std::string& n : m.notes()) ImGui::TextDisabled("guess: %s", n.c_str());
  if (!character_message_.empty()) ImGui::TextDisabled("%s", character_message_.c_str());

  // Parts: pick one (orange), then click a bone in the tree; right-click empties a part.
  ImGui::Separator();
  ImGui::TextUnformatted("Parts (pick one, then click its bone; right-click clears)");
  const RigMapping& map = m.mapping();
  slot_button(m, {RigSlotKind::kRoot, 0}, map.root);
  ImGui::SameLine();
  slot_button(m, {RigSlotKind::kHead, 0}, map.head);
  ImGui::SameLine();
  if (ImGui::SmallButton("Guess from names")) m.guess();
  list_slots(m, RigSlotKind::kSpine, map.spine);
  list_slots(m, RigSlotKind::kNeck, map.neck);
  list_slots(m, RigSlotKind::kTail, map.tail);
  for (int kind = 0; kind < 2; ++kind) {
    const bool legs = kind == 0;
    const std::vector<RigChain>& chains = legs ? map.legs : map.arms;
    for (size_t i = 0; i < chains.size(); ++i) {
      const int idx = static_cast<int>(i);
      ImGui::PushID(legs ? idx : 1000 + idx);
      ImGui::Text("%s[%d]", legs ? "legs" : "arms", idx);
      ImGui::SameLine();
      int side = chains[i].side == Side::kFar ? 1 : 0;
      ImGui::SetNextItemWidth(60);
      static const char* kSides[] = {"near", "far"};
      if (ImGui::Combo("##side", &side, kSides, 2)) m.set_side(legs, idx, side ? Side::kFar : Side::kNear);
      ImGui::SameLine();
      slot_button(m, {legs ? RigSlotKind::kLegUpper : RigSlotKind::kArmUpper, idx}, chains[i].upper);
      ImGui::SameLine();
      slot_button(m, {legs ? RigSlotKind::kLegLower : RigSlotKind::kArmLower, idx}, chains[i].lower);
      ImGui::SameLine();
      slot_button(m, {legs ? RigSlotKind::kLegFoot : RigSlotKind::kArmHand, idx}, chains[i].end);
      ImGui::SameLine();
      if (ImGui::SmallButton("x")) legs ? m.remove_leg(idx) : m.remove_arm(idx);
      ImGui::PopID();
    }
  }
  if (ImGui::SmallButton("Add leg")) m.add_leg();
  ImGui::SameLine();
  if (ImGui::SmallButton("Add arm")) m.add_arm();

  // The bone tree.
  ImGui::Separator();
  ImGui::Text("Bones of %s (click: the picked part, %s)", m.skeleton().source.c_str(), rig_slot_field(m.slot()).c_str());
  ImGui::BeginChild("##bones", ImVec2(0, 0), true);
  for (int r : m.roots()) bone_tree(m, r);
  ImGui::EndChild();
  ImGui::End();
}

}  // namespace ossa

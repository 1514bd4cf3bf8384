#include "ossa/editor/rig_editor_model.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "ossa/io/json.h"
#include "ossa/rig/rig_guess.h"
#include "ossa/game/player.h"
#include "ossa/render/character_mesh.h"

namespace ossa {

namespace {

constexpr float kPreviewDt = 1.0f / 120.0f;
constexpr float kPreviewWrap = 400.0f;  // metres: the preview walks back to the start past this

std::vector<std::string>* list_of(RigMapping& m, RigSlotKind kind) {
  switch (kind) {
    case RigSlotKind::kSpine: return &m.spine;
    case RigSlotKind::kNeck: return &m.neck;
    case RigSlotKind::kTail: return &m.tail;
    default: return nullptr;
  }
}

std::string* field_of(RigMapping& m, const RigSlot& s) {
  auto chain = [&](std::vector<RigChain>& list, int part) -> std::string* {
    if (s.index < 0 || s.index >= static_cast<int>(list.size())) return nullptr;
    RigChain& c = list[static_cast<size_t>(s.index)];
    return part == 0 ? &c.upper : part == 1 ? &c.lower : &c.end;
  };
  switch (s.kind) {
    case RigSlotKind::kRoot: return &m.root;
    case RigSlotKind::kHead: return &m.head;
    case RigSlotKind::kLegUpper: return chain(m.legs, 0);
    case RigSlotKind::kLegLower: return chain(m.legs, 1);
    case RigSlotKind::kLegFoot: return chain(m.legs, 2);
    case RigSlotKind::kArmUpper: return chain(m.arms, 0);
    case RigSlotKind::kArmLower: return chain(m.arms, 1);
    case RigSlotKind::kArmHand: return chain(m.arms, 2);
    default: {
      std::vector<std::string>* list = list_of(m, s.kind);
      if (!list || s.index < 0 || s.index >= static_cast<int>(list->size())) return nullptr;
      return &(*list)[static_cast<size_t>(s.index)];
    }
  }
}

// Every slot of a mapping, in file order.
std::vector<RigSlot> slots_of(const RigMapping& m) {
  std::vector<RigSlot> out = {{RigSlotKind::kRoot, 0}};
  for (size_t i = 0; i < m.spine.size(); ++i) out.push_back({RigSlotKind::kSpine, static_cast<int>(i)});
  for (size_t i = 0; i < m.neck.size(); ++i) out.push_back({RigSlotKind::kNeck, static_cast<int>(i)});
  out.push_back({RigSlotKind::kHead, 0});
  for (size_t i = 0; i < m.tail.size(); ++i) out.push_back({RigSlotKind::kTail, static_cast<int>(i)});
  for (size_t i = 0; i < m.legs.size(); ++i) {
    for (RigSlotKind k : {RigSlotKind::kLegUpper, RigSlotKind::kLegLower, RigSlotKind::kLegFoot}) out.push_back({k, static_cast<int>(i)});
  }
  for (size_t i = 0; i < m.arms.size(); ++i) {
    for (RigSlotKind k : {RigSlotKind::kArmUpper, RigSlotKind::kArmLower, RigSlotKind::kArmHand}) out.push_back({k, static_cast<int>(i)});
  }
  return out;
}

}  // namespace

std::string rig_slot_field(const RigSlot& s) {
  switch (s.kind) {
    case RigSlotKind::kRoot: return "root";
    case RigSlotKind::kSpine: return json_path("spine", static_cast<size_t>(s.index));
    case RigSlotKind::kNeck: return json_path("neck", static_cast<size_t>(s.index));
    case RigSlotKind::kHead: return "head";
    case RigSlotKind::kTail: return json_path("tail", static_cast<size_t>(s.index));
    case RigSlotKind::kLegUpper: return json_path(json_path("legs", static_cast<size_t>(s.index)), "upper");
    case RigSlotKind::kLegLower: return json_path(json_path("legs", static_cast<size_t>(s.index)), "lower");
    case RigSlotKind::kLegFoot: return json_path(json_path("legs", static_cast<size_t>(s.index)), "foot");
    case RigSlotKind::kArmUpper: return json_path(json_path("arms", static_cast<size_t>(s.index)), "upper");
    case RigSlotKind::kArmLower: return json_path(json_path("arms", static_cast<size_t>(s.index)), "lower");
    case RigSlotKind::kArmHand: return json_path(json_path("arms", static_cast<size_t>(s.index)), "hand");
  }
  return "";
}

RigEditorModel::RigEditorModel(UndoStack& undo)
    : undo_(&undo), preview_level_({Box::from_corner(-kPreviewWrap - 50.0f, -1.0f, 2.0f * kPreviewWrap + 100.0f, 1.0f)}) {}

Status RigEditorModel::open_mapping(const std::string& rig_path) {
  Result<RigMapping> m = load_rig_mapping(rig_path);
  if (!m.ok()) {
    file_error_ = m.message();
    return m.error();
  }
  Result<RiggedMesh> mesh = load_rigged_mesh(m->mesh_path);
  if (!mesh.ok()) {
    file_error_ = rig_path + ": mesh: " + mesh.message();
    return Error{file_error_};
  }
  (void)load_rigged_texture(mesh.value());  // the preview's colours; without one it is grey
  open(std::move(mesh.value()), *m, rig_path);
  return {};
}

Status RigEditorModel::open_mesh(const std::string& mesh_path, const std::string& rig_path) {
  Result<RiggedMesh> mesh = load_rigged_mesh(mesh_path);
  if (!mesh.ok()) {
    file_error_ = mesh.message();
    return mesh.error();
  }
  (void)load_rigged_texture(mesh.value());  // the preview's colours; without one it is grey
  namespace fs = std::filesystem;
  std::string path = rig_path;
  if (path.empty()) path = (fs::path(mesh_path).parent_path() / (fs::path(mesh_path).stem().string() + ".rig.json")).string();
  const RigGuess g = guess_rig_mapping(imported_skeleton(*mesh), fs::path(mesh_path).filename().string());
  RigMapping m = g.mapping;
  m.mesh_path = mesh_path;
  m.mesh = fs::absolute(mesh_path).lexically_relative(fs::absolute(path).parent_path()).generic_string();
  open(std::move(mesh.value()), m, path);
  notes_ = g.notes;
  undo_->clear(EditorDocument::kRig);
  // A guess is new work: unsaved until the designer saves it.
  undo_->push({"guess", EditorDocument::kRig, [] {}, [] {}}, true);
  return {};
}

void RigEditorModel::open(RiggedMesh mesh, RigMapping mapping, const std::string& rig_path) {
  mesh_ = std::make_unique<RiggedMesh>(std::move(mesh));
  skeleton_ = imported_skeleton(*mesh_);
  children_.assign(skeleton_.bones.size(), {});
  for (size_t i = 0; i < skeleton_.bones.size(); ++i) {
    const int p = skeleton_.bones[i].parent;
    if (p >= 0) children_[static_cast<size_t>(p)].push_back(static_cast<int>(i));
  }
  path_ = rig_path;
  slot_ = {};
  notes_.clear();
  file_error_.clear();
  apply(mapping);
  undo_->clear(EditorDocument::kRig);
}

std::vector<int> RigEditorModel::roots() const {
  std::vector<int> out;
  for (size_t i = 0; i < skeleton_.bones.size(); ++i) {
    if (skeleton_.bones[i].parent < 0) out.push_back(static_cast<int>(i));
  }
  return out;
}

std::string RigEditorModel::part_of(int bone) const {
  if (bone < 0 || bone >= static_cast<int>(skeleton_.bones.size())) return "";
  for (const auto& [field, name] : rig_mapping_bones(mapping_)) {
    if (name == skeleton_.bones[static_cast<size_t>(bone)].name) return field;
  }
  return "";
}

int RigEditorModel::bone_of(const RigSlot& slot) const {
  RigMapping m = mapping_;
  const std::string* f = field_of(m, slot);
  return f && !f->empty() ? skeleton_.find(*f) : -1;
}

void RigEditorModel::apply(const RigMapping& m) {
  mapping_ = m;
  rebuild();
}

void RigEditorModel::rebuild() {
  character_.reset();
  preview_.reset();
  error_.clear();
  if (!mesh_) return;
  Result<Character> c = build_character(skeleton_, mapping_, path_);
  if (!c.ok()) {
    error_ = c.message();
    return;
  }
  character_ = std::make_shared<const Character>(std::move(c.value()));
  preview_ = std::make_unique<Animator>(character_->rig, SplinePrototypes::defaults());
  preview_->reset({0.0f, 1.0f}, preview_level_);
  preview_clock_ = 0.0f;
}

void RigEditorModel::push(const std::string& label, const RigMapping& after) {
  const RigMapping before = mapping_;
  undo_->push({label, EditorDocument::kRig, [this, after] { apply(after); }, [this, before] { apply(before); }});
}

void RigEditorModel::set_mapping(const RigMapping& mapping, const std::string& label) {
  RigMapping m = mapping;
  m.mesh = mapping_.mesh;
  m.mesh_path = mapping_.mesh_path;
  push(label, m);
}

void RigEditorModel::assign(const RigSlot& slot, int bone) {
  if (!mesh_ || bone < 0 || bone >= static_cast<int>(skeleton_.bones.size())) return;
  const std::string& name = skeleton_.bones[static_cast<size_t>(bone)].name;
  RigMapping m = mapping_;
  // The bone leaves any part it had (a list entry is removed; a chain's field is emptied).
  for (const RigSlot& s : slots_of(m)) {
    if (s == slot) continue;
    std::string* f = field_of(m, s);
    if (f && *f == name) f->clear();
  }
  for (RigSlotKind k : {RigSlotKind::kSpine, RigSlotKind::kNeck, RigSlotKind::kTail}) {
    std::vector<std::string>* list = list_of(m, k);
    if (!(slot.kind == k)) list->erase(std::remove(list->begin(), list->end(), std::string()), list->end());
  }
  std::vector<std::string>* list = list_of(m, slot.kind);
  if (list && slot.index >= static_cast<int>(list->size())) {
    list->push_back(name);
  } else if (std::string* f = field_of(m, slot)) {
    *f = name;
  } else {
    return;
  }
  if (list) list->erase(std::remove(list->begin(), list->end(), std::string()), list->end());
  push("assign " + name + " to " + rig_slot_field(slot), m);
  // On to the next part of the chain.
  switch (slot.kind) {
    case RigSlotKind::kLegUpper: slot_ = {RigSlotKind::kLegLower, slot.index}; break;
    case RigSlotKind::kLegLower: slot_ = {RigSlotKind::kLegFoot, slot.index}; break;
    case RigSlotKind::kArmUpper: slot_ = {RigSlotKind::kArmLower, slot.index}; break;
    case RigSlotKind::kArmLower: slot_ = {RigSlotKind::kArmHand, slot.index}; break;
    case RigSlotKind::kSpine:
    case RigSlotKind::kNeck:
    case RigSlotKind::kTail: slot_ = {slot.kind, static_cast<int>(list_of(mapping_, slot.kind)->size())}; break;
    default: slot_ = slot; break;
  }
}

void RigEditorModel::clear(const RigSlot& slot) {
  RigMapping m = mapping_;
  std::vector<std::string>* list = list_of(m, slot.kind);
  if (list) {
    if (slot.index < 0 || slot.index >= static_cast<int>(list->size())) return;
    list->erase(list->begin() + slot.index);
  } else if (std::string* f = field_of(m, slot)) {
    f->clear();
  } else {
    return;
  }
  push("clear " + rig_slot_field(slot), m);
}

void RigEditorModel::add_leg() {
  RigMapping m = mapping_;
  RigChain leg;
  leg.side = m.legs.size() % 2 == 0 ? Side::kNear : Side::kFar;
  m.legs.push_back(leg);
  push("add a leg", m);
  slot_ = {RigSlotKind::kLegUpper, static_cast<int>(m.legs.size()) - 1};
}

void RigEditorModel::add_arm() {
  RigMapping m = mapping_;
  RigChain arm;
  arm.side = m.arms.size() % 2 == 0 ? Side::kNear : Side::kFar;
  m.arms.push_back(arm);
  push("add an arm", m);
  slot_ = {RigSlotKind::kArmUpper, static_cast<int>(m.arms.size()) - 1};
}

void RigEditorModel::remove_leg(int leg) {
  if (leg < 0 || leg >= static_cast<int>(mapping_.legs.size())) return;
  RigMapping m = mapping_;
  m.legs.erase(m.legs.begin() + leg);
  push("remove legs[" + std::to_string(leg) + "]", m);
}

void RigEditorModel::remove_arm(int arm) {
  if (arm < 0 || arm >= static_cast<int>(mapping_.arms.size())) return;
  RigMapping m = mapping_;
  m.arms.erase(m.arms.begin() + arm);
  push("remove arms[" + std::to_string(arm) + "]", m);
}

void RigEditorModel::set_side(bool leg, int index, Side side) {
  RigMapping m = mapping_;
  std::vector<RigChain>& list = leg ? m.legs : m.arms;
  if (index < 0 || index >= static_cast<int>(list.size()) || list[static_cast<size_t>(index)].side == side) return;
  list[static_cast<size_t>(index)].side = side;
  push(std::string("side of ") + (leg ? "legs[" : "arms[") + std::to_string(index) + "]", m);
}

void RigEditorModel::set_contact(int leg, std::optional<glm::vec2> contact) {
  if (leg < 0 || leg >= static_cast<int>(mapping_.legs.size())) return;
  RigMapping m = mapping_;
  m.legs[static_cast<size_t>(leg)].contact = contact;
  push("contact of legs[" + std::to_string(leg) + "]", m);
}

void RigEditorModel::guess() {
  if (!mesh_) return;
  const RigGuess g = guess_rig_mapping(skeleton_, mapping_.mesh);
  notes_ = g.notes;
  set_mapping(g.mapping, "guess from bone names");
}

void RigEditorModel::step_preview(float dt) {
  if (!preview_ || !(dt > 0.0f)) return;
  // The Player's stick mapping: half a stick is the walk speed, a full one the run speed.
  const float a = std::clamp(std::fabs(preview_stick), 0.0f, 1.0f);
  const float walk = preview_->walk_speed(), run = preview_->run_speed();
  const float speed = std::copysign(a <= 0.5f ? 2.0f * a * walk : walk + (2.0f * a - 1.0f) * (run - walk), preview_stick);
  preview_clock_ += std::min(dt, 0.25f);
  while (preview_clock_ >= kPreviewDt) {
    preview_clock_ -= kPreviewDt;
    preview_->update(kPreviewDt, speed, preview_level_);
  }
  if (std::fabs(preview_->x()) > kPreviewWrap) preview_->reset({0.0f, 1.0f}, preview_level_, preview_->facing());
}

Status RigEditorModel::save_as(const std::string& rig_path) {
  if (!mesh_) return Error{"nothing to save: open a mesh or a mapping first"};
  namespace fs = std::filesystem;
  RigMapping m = mapping_;
  // "mesh" stays relative to where the mapping now lives.
  m.mesh = fs::absolute(m.mesh_path).lexically_relative(fs::absolute(rig_path).parent_path()).generic_string();
  if (Status s = save_rig_mapping(rig_path, m); !s.ok()) {
    file_error_ = s.message();
    return s;
  }
  mapping_.mesh = m.mesh;
  path_ = rig_path;
  file_error_.clear();
  undo_->mark_saved(EditorDocument::kRig);
  return {};
}

}  // namespace ossa

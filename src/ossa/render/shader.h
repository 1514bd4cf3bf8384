#pragma once
// ShaderProgram — a GLSL 330 core program loaded from a vertex and a fragment file at run
// time ([T 4.3.1]: DebugShader, TexturedShader, RiggedShader, BoneShader are instances).
//
// Compile and link errors name the file and line: the driver's log ("0:12(5): error: ..."
// from Mesa, "0(12) : error ..." from NVIDIA) is rewritten as "shaders/x.frag:12:5: error: ...".
// reload_if_changed() watches both files' modification times; a failed reload logs the error
// and keeps the previous, working program, so editing a shader while running never blanks
// the screen.

#include <string>
#include <string_view>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "ossa/io/result.h"

namespace ossa {

// Rewrites a driver info log so that every "0:LINE(COL)" or "0(LINE)" location becomes
// "file:LINE[:COL]"; lines without a location are kept as they are.
std::string format_shader_log(std::string_view log, std::string_view file);

class ShaderProgram {
 public:
  // Compiles and links; the error message names the file and line of the first problem.
  static Result<ShaderProgram> load(const std::string& vertex_path,
                                    const std::string& fragment_path);

  ShaderProgram() = default;
  ~ShaderProgram();
  ShaderProgram(ShaderProgram&& o) noexcept;
  ShaderProgram& operator=(ShaderProgram&& o) noexcept;
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  bool is_valid() const { return id_ != 0; }
  unsigned id() const { return id_; }
  const std::string& vertex_path() const { return vertex_path_; }
  const std::string& fragment_path() const { return fragment_path_; }

  // Recompiles when either file changed since the last (attempted) load. Returns true when a
  // new program replaced the old one; on failure logs the error and keeps the old program.
  bool reload_if_changed();

  void use() const;
  // Uniform setters on the program in use; unknown names are ignored (location -1).
  int location(const char* name) const;
  void set(const char* name, int v) const;
  void set(const char* name, float v) const;
  void set(const char* name, glm::vec2 v) const;
  void set(const char* name, glm::vec4 v) const;
  void set(const char* name, const glm::mat3& m) const;

 private:
  unsigned id_ = 0;
  std::string vertex_path_, fragment_path_;
  long long vertex_mtime_ = 0, fragment_mtime_ = 0;  // nanoseconds since epoch
};

}  // namespace ossa

#include "ossa/render/shader.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <utility>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "ossa/io/file.h"
#include "ossa/render/gl.h"

namespace ossa {
namespace {

long long mtime_ns(const std::string& path) {
  std::error_code ec;
  auto t = std::filesystem::last_write_time(path, ec);
  if (ec) return 0;
  return static_cast<long long>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(t.time_since_epoch()).count());
}

// Parses digits at s[i...]; returns -1 when there are none.
long parse_int(std::string_view s, size_t& i) {
  if (i >= s.size() || !std::isdigit(static_cast<unsigned char>(s[i]))) return -1;
  long v = 0;
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) v = v * 10 + (s[i++] - '0');
  return v;
}

std::string format_line(std::string_view line, std::string_view file) {
  // Mesa: "0:LINE(COL): msg"; NVIDIA: "0(LINE) : msg"; both start with the source string 0.
  size_t i = 0;
  if (parse_int(line, i) < 0 || i >= line.size()) return std::string(line);
  long row = -1, col = -1;
  if (line[i] == ':') {
    ++i;
    row = parse_int(line, i);
    if (row < 0 || i >= line.size() || line[i] != '(') return std::string(line);
    ++i;
    col = parse_int(line, i);
    if (col < 0 || i >= line.size() || line[i] != ')') return std::string(line);
    ++i;
  } else if (line[i] == '(') {
    ++i;
    row = parse_int(line, i);
    if (row < 0 || i >= line.size() || line[i] != ')') return std::string(line);
    ++i;
  } else {
    return std::string(line);
  }
  while (i < line.size() && (line[i] == ' ' || line[i] == ':')) ++i;
  std::string out(file);
  out += ":" + std::to_string(row);
  if (col >= 0) out += ":" + std::to_string(col);
  out += ": ";
  out += line.substr(i);
  return out;
}

Result<unsigned> compile(GLenum type, const std::string& path) {
  auto text = read_file(path);
  if (!text.ok()) return Error{text.message()};
  const GLuint shader = glCreateShader(type);
  const char* src = text.value().c_str();
  glShaderSource(shader, 1, &src, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<size_t>(std::max(len, 1)), '\0');
    glGetShaderInfoLog(shader, len, nullptr, log.data());
    glDeleteShader(shader);
    log.resize(std::strlen(log.c_str()));
    std::string msg = format_shader_log(log, path);
    if (msg.empty()) msg = path + ": compile failed";
    return Error{msg};
  }
  return static_cast<unsigned>(shader);
}

Result<unsigned> build(const std::string& vs_path, const std::string& fs_path) {
  auto vs = compile(GL_VERTEX_SHADER, vs_path);
  if (!vs.ok()) return Error{vs.message()};
  auto fs = compile(GL_FRAGMENT_SHADER, fs_path);
  if (!fs.ok()) {
    glDeleteShader(vs.value());
    return Error{fs.message()};
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs.value());
  glAttachShader(program, fs.value());
  glLinkProgram(program);
  glDeleteShader(vs.value());
  glDeleteShader(fs.value());
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<size_t>(std::max(len, 1)), '\0');
    glGetProgramInfoLog(program, len, nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    glDeleteProgram(program);
    return Error{vs_path + " + " + fs_path + ": link failed: " + log};
  }
  return static_cast<unsigned>(program);
}

}  // namespace

std::string format_shader_log(std::string_view log, std::string_view file) {
  std::string out;
  size_t start = 0;
  while (start < log.size()) {
    size_t end = log.find('\n', start);
    if (end == std::string_view::npos) end = log.size();
    std::string_view line = log.substr(start, end - start);
    if (!line.empty()) {
      if (!out.empty()) out += '\n';
      out += format_line(line, file);
    }
    start = end + 1;
  }
  return out;
}

Result<ShaderProgram> ShaderProgram::load(const std::string& vertex_path,
                                          const std::string& fragment_path) {
  ShaderProgram p;
  p.vertex_path_ = vertex_path;
  p.fragment_path_ = fragment_path;
  p.vertex_mtime_ = mtime_ns(vertex_path);
  p.fragment_mtime_ = mtime_ns(fragment_path);
  auto id = build(vertex_path, fragment_path);
  if (!id.ok()) return Error{id.message()};
  p.id_ = id.value();
  return p;
}

ShaderProgram::~ShaderProgram() {
  if (id_) glDeleteProgram(id_);
}

ShaderProgram::ShaderProgram(ShaderProgram&& o) noexcept { *this = std::move(o); }

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& o) noexcept {
  if (this != &o) {
    if (id_) glDeleteProgram(id_);
    id_ = std::exchange(o.id_, 0u);
    vertex_path_ = std::move(o.vertex_path_);
    fragment_path_ = std::move(o.fragment_path_);
    vertex_mtime_ = o.vertex_mtime_;
    fragment_mtime_ = o.fragment_mtime_;
  }
  return *this;
}

bool ShaderProgram::reload_if_changed() {
  const long long vt = mtime_ns(vertex_path_), ft = mtime_ns(fragment_path_);
  if (vt == vertex_mtime_ && ft == fragment_mtime_) return false;
  // Remember the attempt so a broken file is reported once, not every frame.
  vertex_mtime_ = vt;
  fragment_mtime_ = ft;
  auto id = build(vertex_path_, fragment_path_);
  if (!id.ok()) {
    render_log("shader reload failed, keeping the previous program: " + id.message());
    return false;
  }
  if (id_) glDeleteProgram(id_);
  id_ = id.value();
  return true;
}

void ShaderProgram::use() const { glUseProgram(id_); }
int ShaderProgram::location(const char* name) const { return glGetUniformLocation(id_, name); }
void ShaderProgram::set(const char* name, int v) const { glUniform1i(location(name), v); }
void ShaderProgram::set(const char* name, float v) const { glUniform1f(location(name), v); }
void ShaderProgram::set(const char* name, glm::vec2 v) const {
  glUniform2f(location(name), v.x, v.y);
}
void ShaderProgram::set(const char* name, glm::vec4 v) const {
  glUniform4f(location(name), v.x, v.y, v.z, v.w);
}
void ShaderProgram::set(const char* name, const glm::mat3& m) const {
  glUniformMatrix3fv(location(name), 1, GL_FALSE, glm::value_ptr(m));
}

}  // namespace ossa

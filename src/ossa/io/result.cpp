#include "ossa/io/result.h"

namespace ossa {

Error Error::at(std::string_view file, std::string_view field, std::string_view what) {
  std::string m;
  if (!file.empty()) m.append(file).append(": ");
  if (!field.empty()) m.append(field).append(": ");
  m.append(what);
  return Error{std::move(m)};
}

}  // namespace ossa

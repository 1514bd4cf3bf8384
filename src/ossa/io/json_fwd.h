#pragma once
// The names of ossa's JSON types without nlohmann/json's definitions: headers that only declare
// functions taking or returning a Json include this; the code that builds or reads a document
// includes ossa/io/json.h (nlohmann/json.hpp is the largest header ossa uses: about 1.4 s of
// every compile that includes it).

#include <nlohmann/json_fwd.hpp>

namespace ossa {

using Json = nlohmann::json;
class JsonReader;

}  // namespace ossa

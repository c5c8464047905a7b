#include "core/launch/config_tree.h"

namespace avc::launch {

const char* KindName(ConfigValue::Kind kind) {
  switch (kind) {
    case ConfigValue::Kind::kNull:
      return "empty";
    case ConfigValue::Kind::kString:
      return "a string";
    case ConfigValue::Kind::kNumber:
      return "a number";
    case ConfigValue::Kind::kBool:
      return "a boolean";
    case ConfigValue::Kind::kArray:
      return "a list";
    case ConfigValue::Kind::kTable:
      return "a table";
    case ConfigValue::Kind::kOther:
      return "a date or time";
  }
  return "a value";
}

}  // namespace avc::launch

#pragma once
// The rviz property classes the property groups hold, and the Config they load from (their
// headers only in the .cpp files).

namespace rviz {
class BoolProperty;
class Config;
class ColorProperty;
class EnumProperty;
class FloatProperty;
class IntProperty;
class Property;
class RosTopicProperty;
class StringProperty;
class VectorProperty;
}  // namespace rviz

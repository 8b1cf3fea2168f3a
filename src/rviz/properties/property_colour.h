#pragma once
// A colour property's value as the core's opaque RGBA.

#include <Eigen/Core>
#include <QColor>

namespace dressed_human {

inline Eigen::Vector4f opaqueRgba(const QColor& colour) {
  return Eigen::Vector4f(static_cast<float>(colour.redF()), static_cast<float>(colour.greenF()),
                         static_cast<float>(colour.blueF()), 1.0f);
}

}  // namespace dressed_human

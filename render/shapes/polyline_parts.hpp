#pragma once
// makePolyline's union with its capsules named, for a caller that traces a
// segment against only the capsules it passes near and must get the union's
// very answers: the rasterizer (lht/raster/lattice_object.hpp). The capsules
// are the union's own children, so each answers exactly as it does inside it.
#include <vector>

#include "render/shapes/polyline_shape.hpp"

namespace lattice {

// makePolyline(points, radius, objectToWorld, material), and in `parts` its
// capsules in the order of the points (capsule k from point k to k + 1),
// owned by the returned union (a lone capsule is itself the result).
template <typename T>
PrimitivePtr<T> makePolylineNamingParts(const std::vector<Vec3d>& points, double radius, const Mat4d& objectToWorld,
                                        MaterialId material, std::vector<const Primitive<T>*>& parts);

extern template PrimitivePtr<double> makePolylineNamingParts<double>(const std::vector<Vec3d>&, double, const Mat4d&,
                                                                     MaterialId, std::vector<const Primitive<double>*>&);

}  // namespace lattice

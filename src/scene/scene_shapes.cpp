// Shapes of bodies and regions: box, circle/sphere, ring/hollow_sphere, cylinder, polygon, union,
// difference.
#include "scene/scene_parts.hpp"

namespace monosph {

Shape read_shape(const YAML::Node& node, const std::string& path, int dim,
                 const Constants* constants) {
  static const std::vector<std::string> kinds = {"box",     "circle",        "sphere",
                                                 "ring",    "hollow_sphere", "cylinder",
                                                 "polygon", "union",         "difference"};
  if (!node.IsMap() || node.size() != 1)
    scene_error(path,
                "expected a map with exactly one shape key (box, circle, sphere, ring, "
                "hollow_sphere, cylinder, polygon, union, difference)");
  std::string kind = node.begin()->first.as<std::string>();
  YAML::Node body = node.begin()->second;
  std::string p = path + "." + kind;
  Shape s;
  auto list_of_shapes = [&](Shape::Kind k) {
    if (!body.IsSequence() || body.size() < 1) scene_error(p, "expected a list of shapes");
    s.kind = k;
    for (std::size_t i = 0; i < body.size(); ++i)
      s.parts.push_back(read_shape(body[i], p + "[" + std::to_string(i) + "]", dim, constants));
    if (k == Shape::Kind::Difference && s.parts.size() < 2)
      scene_error(p, "expected a base shape followed by at least one shape to subtract");
  };
  if (kind == "box") {
    MapReader r(body, p, constants);
    s.kind = Shape::Kind::Box;
    s.a = r.vector("min", dim);
    s.b = r.vector("max", dim);
    r.finish();
    for (int k = 0; k < dim; ++k)
      if (!(s.b[k] > s.a[k])) scene_error(p + ".max", "must be greater than min in every axis");
  } else if ((kind == "circle" && dim == 2) || (kind == "sphere" && dim == 3)) {
    MapReader r(body, p, constants);
    s.kind = Shape::Kind::Sphere;
    s.center = r.vector("center", dim);
    s.r0 = r.positive("radius");
    r.finish();
  } else if ((kind == "ring" && dim == 2) || (kind == "hollow_sphere" && dim == 3)) {
    MapReader r(body, p, constants);
    s.kind = Shape::Kind::Ring;
    s.center = r.vector("center", dim);
    s.r0 = r.positive("inner");
    s.r1 = r.positive("outer");
    r.finish();
    if (!(s.r1 > s.r0)) scene_error(p + ".outer", "must be greater than inner");
  } else if (kind == "cylinder" && dim == 3) {
    MapReader r(body, p, constants);
    s.kind = Shape::Kind::Cylinder;
    s.a = r.vector("start", 3);
    s.b = r.vector("end", 3);
    s.r0 = r.positive("radius");
    r.finish();
  } else if (kind == "polygon" && dim == 2) {
    MapReader r(body, p, constants);
    s.kind = Shape::Kind::Polygon;
    auto v = r.node("vertices");
    if (!v.IsSequence() || v.size() < 3) scene_error(p + ".vertices", "expected at least 3 points");
    for (std::size_t i = 0; i < v.size(); ++i)
      s.vertices.push_back(
          as_vector(v[i], p + ".vertices[" + std::to_string(i) + "]", 2, constants));
    r.finish();
  } else if (kind == "union") {
    list_of_shapes(Shape::Kind::Union);
  } else if (kind == "difference") {
    list_of_shapes(Shape::Kind::Difference);
  } else {
    std::string hint = closest_word(kind, kinds);
    scene_error(p, "unknown shape in " + std::to_string(dim) +
                       "D (allowed: box, union, difference, " +
                       (dim == 2 ? "circle, ring, polygon)" : "sphere, hollow_sphere, cylinder)") +
                       (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
  }
  return s;
}

}  // namespace monosph

#include "output/checkpoint_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

namespace monosph {

namespace {

const Field* find(const std::vector<Field>& fields, const std::string& name) {
  auto it =
      std::find_if(fields.begin(), fields.end(), [&](const Field& f) { return f.name == name; });
  return it == fields.end() ? nullptr : &*it;
}

// "particle 7 (id 123)" (the id only when the id field is there and the row has one).
std::string particle(const std::vector<Field>& fields, std::size_t i) {
  const Field* id = find(fields, "id");
  if (id && id->type == FieldType::Int && i < id->ints.size())
    return fmt::format("particle {} (id {})", i, id->ints[i]);
  return fmt::format("particle {}", i);
}

std::string check_meta(const CheckpointMeta& m) {
  if (!std::isfinite(m.time) || m.time < 0)
    return fmt::format("meta time {} is not a time", m.time);
  if (!std::isfinite(m.dt) || m.dt < 0) return fmt::format("meta dt {} is not a time step", m.dt);
  if (m.step < 0) return fmt::format("meta step {} is negative", m.step);
  if (m.next_id < 0) return fmt::format("meta next_id {} is negative", m.next_id);
  for (const auto& [k, v] : m.scalars)
    if (!std::isfinite(v)) return fmt::format("module state '{}' = {} is not finite", k, v);
  return "";
}

std::string check_ids(const std::vector<Field>& fields, std::int64_t next_id) {
  const Field* id = find(fields, "id");
  if (!id || id->type != FieldType::Int || id->ncomp != 1) return "";
  std::vector<std::pair<std::int64_t, std::size_t>> sorted;
  sorted.reserve(id->ints.size());
  for (std::size_t i = 0; i < id->ints.size(); ++i) {
    const std::int64_t v = id->ints[i];
    if (v < 0 || v >= next_id)
      return fmt::format("field 'id', particle {}: id {} outside [0, next_id = {})", i, v, next_id);
    sorted.emplace_back(v, i);
  }
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t k = 1; k < sorted.size(); ++k)
    if (sorted[k].first == sorted[k - 1].first)
      return fmt::format("field 'id': particles {} and {} have the same id {}",
                         sorted[k - 1].second, sorted[k].second, sorted[k].first);
  return "";
}

// The problem with index field `name` (values in [lo, hi)), "" if none or no such field.
std::string check_range(const std::vector<Field>& fields, const std::string& name, std::int64_t lo,
                        std::int64_t hi, const std::string& what) {
  const Field* f = find(fields, name);
  if (!f) return "";
  if (f->type != FieldType::Int || f->ncomp != 1)
    return "field '" + name + "' is not an integer field";
  for (std::size_t i = 0; i < f->ints.size(); ++i) {
    const std::int64_t v = f->ints[i];
    if (v < lo || v >= hi)
      return fmt::format("field '{}', {}: {} {} out of range [{}, {}) ({})", name,
                         particle(fields, i), name, v, lo, hi, what);
  }
  return "";
}

// clusters.count of the module state: a whole number of clusters, at most one per particle.
std::optional<std::int64_t> cluster_count(const CheckpointMeta& meta, std::size_t n,
                                          std::string& err) {
  auto it = meta.scalars.find("clusters.count");
  if (it == meta.scalars.end()) return std::nullopt;
  const double c = it->second;
  if (!(c >= 0 && c <= static_cast<double>(n) && c == std::floor(c)))
    err = fmt::format("module state 'clusters.count' = {} is not a number of clusters (0 to {})", c,
                      n);
  return static_cast<std::int64_t>(std::clamp(c, 0.0, static_cast<double>(n)));
}

Phase phase_of(const std::string& name) {
  return name == "fluid" ? kFluid : name == "wall" ? kWall : name == "rigid" ? kRigid : kSolid;
}

// Each particle has the phase and material of its body (neither ever changes in a run).
std::string check_bodies(const std::vector<Field>& fields, const Scene& scene) {
  const Field *ph = find(fields, "phase"), *mt = find(fields, "material"),
              *bd = find(fields, "body");
  if (!ph || !mt || !bd) return "";
  for (std::size_t i = 0; i < bd->ints.size(); ++i) {
    const BodySpec& b = scene.bodies[static_cast<std::size_t>(bd->ints[i])];
    if (ph->ints[i] != phase_of(b.phase))
      return fmt::format("field 'phase', {}: phase {} is not that of its body '{}' ({})",
                         particle(fields, i), ph->ints[i], b.name, b.phase);
    if (mt->ints[i] != b.material)
      return fmt::format("field 'material', {}: material {} is not that of its body '{}' ({})",
                         particle(fields, i), mt->ints[i], b.name, b.material);
  }
  return "";
}

// Every position within the domain on its non-periodic axes, give or take what a particle may
// move between two neighbour rebuilds (which catch one that leaves): a kernel support and the
// skin. A position beyond could not come from a run; it would stop the restart at its first step.
// The same for the positions of the last rebuild, from which a restart makes its lists.
std::string check_positions(const std::vector<Field>& fields, const Scene& scene) {
  const int dim = scene.dimension;
  const double slack = (3 + scene.skin_factor) * scene.h();
  for (const char* name : {"position", "build_position"}) {
    const Field* x = find(fields, name);
    if (!x || x->type != FieldType::Real) continue;
    for (std::size_t i = 0; i * dim < x->real.size(); ++i)
      for (int a = 0; a < dim; ++a) {
        const double v = x->real[i * dim + a];
        const double lo = scene.domain_min[a], hi = scene.domain_max[a];
        if (!scene.periodic[a] && (v < lo - slack || v > hi + slack))
          return fmt::format(
              "field '{}', {}: {} = {:g} lies outside the domain [{:g}, {:g}] by more than a run "
              "lets a particle move (the checkpoint is damaged)",
              name, particle(fields, i), "xyz"[a], v, lo, hi);
      }
  }
  return "";
}

}  // namespace

std::string check_checkpoint_data(const std::vector<Field>& fields, const CheckpointMeta& meta) {
  if (auto e = check_meta(meta); !e.empty()) return e;
  for (const Field& f : fields) {
    if (f.type != FieldType::Real) continue;
    for (std::size_t k = 0; k < f.real.size(); ++k)
      if (!std::isfinite(f.real[k]))
        return fmt::format("field '{}', {}: non-finite value {}", f.name,
                           particle(fields, k / f.ncomp), f.real[k]);
  }
  return check_ids(fields, meta.next_id);
}

template <int D>
void check_checkpoint_indices(const std::filesystem::path& file, const Particles<D>& p,
                              const CheckpointMeta& meta, const Scene& scene) {
  const auto& f = p.fields();
  const auto nm = static_cast<std::int64_t>(scene.materials.size());
  const auto nb = static_cast<std::int64_t>(scene.bodies.size());
  const auto nbc = static_cast<std::int64_t>(scene.boundaries.size());
  std::string err = check_range(f, "phase", kFluid, kWall + 1, "fluid, solid, rigid, wall");
  if (err.empty()) err = check_range(f, "material", 0, nm, fmt::format("{} materials", nm));
  if (err.empty()) err = check_range(f, "body", 0, nb, fmt::format("{} bodies", nb));
  if (err.empty())
    err = check_range(f, "boundary", 0, nbc + 1, fmt::format("{} boundary conditions", nbc));
  if (err.empty()) {
    const auto nc = cluster_count(meta, p.size(), err);
    const std::int64_t hi = nc ? *nc : std::numeric_limits<std::int64_t>::max();
    if (err.empty())
      err = check_range(f, "cluster", -1, hi,
                        nc ? fmt::format("-1 or one of {} clusters", *nc) : "-1 or a cluster");
  }
  if (err.empty()) err = check_bodies(f, scene);
  if (err.empty()) err = check_positions(f, scene);
  if (!err.empty()) throw InputError("checkpoint " + file.string() + ": " + err);
}

template void check_checkpoint_indices<2>(const std::filesystem::path&, const Particles<2>&,
                                          const CheckpointMeta&, const Scene&);
template void check_checkpoint_indices<3>(const std::filesystem::path&, const Particles<3>&,
                                          const CheckpointMeta&, const Scene&);

}  // namespace monosph

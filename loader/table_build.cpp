#include "loader/table_build.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <functional>

#include "foundation/error.hpp"
#include "lht/raster/lattice_object.hpp"
#include "lht/raster/raster_estimate.hpp"
#include "loader/lattice_scene_loader.hpp"

namespace lattice::lht {

namespace {

// The steps every table goes through; `hashFor` names the object for the
// form the table ends up in; `admit` (may be empty) sees the estimate before
// any work and bounds the hits the rasterizer may hold.
BuiltTable packTable(const LatticeObject& object, double lambda, double oversample, const TableSettings& settings,
                     LhtForm tableForm,
                     const std::function<LhtPrecision(std::uint64_t, std::uint64_t)>& chooseForm,
                     const std::function<std::uint64_t(LhtPrecision)>& hashFor,
                     const std::function<RasterAllowance(LazyRasterEstimate&)>& admit = {}) {
  const bool rasterized = withForm(
      tableForm, [](auto i) { return RasterizedForm<FormAt<decltype(i)::value>>; }, [] { return false; });
  if (!rasterized)
    throw Error(ErrorKind::Usage, fmt::format("an {} table is built while rendering, not rasterized; use --form {}",
                                              lhtFormName(tableForm), lhtFiledFormNames()));
  BuiltTable built;
  LhtFile& lht = built.lht;
  lht.box = LatticeBox(object.bounds, lambda, oversample);
  RasterOptions options;
  options.progress = settings.progress;
  options.threads = settings.threads;
  RasterAllowance allowance;
  if (admit) {
    LazyRasterEstimate estimate(lht.box, object, options.threads);
    allowance = admit(estimate);
  }
  options.maxHits = allowance.maxHits;
  const RasterResult raster = [&] {
    try {
      return rasterize(lht.box, object, options);
    } catch (const RasterHitLimit& stop) {
      throw Error(ErrorKind::Input, fmt::format("rasterizing stopped at {} hits ({} of {} entry points traced), {}",
                                                stop.hits, stop.pointsDone, stop.points, allowance.refusal));
    }
  }();
  const LhtPrecision form = chooseForm(raster.hits.size(), raster.hits.bytes());
  built.stats = raster.stats;
  lht.objectHash = hashFor(form);
  lht.pairs = raster.stats.pairs;
  lht.hits = raster.stats.hits;
  withForm(
      tableForm,
      [&](auto i) {
        if constexpr (RasterizedForm<FormAt<decltype(i)::value>>)
          lht.table.emplace<decltype(i)::value>(FormAt<decltype(i)::value>::fromHits(raster.hits, lht.box.cells(), form));
      },
      [] {});
  return built;
}

LatticeObject shapeObject(const TableRequest& request) {
  if (request.shape == "sphere") return sphereObject(request.radius);
  if (request.shape == "capsule") return capsuleObject(request.radius, request.length);
  throw Error(ErrorKind::Usage, fmt::format("unknown --shape '{}'; use sphere or capsule", request.shape));
}

LatticeDefinition findDefinition(const TableRequest& request) {
  if (request.name.empty())
    throw Error(ErrorKind::Usage, "--scene needs --name NAME, the [[lattices]] entry to rasterize");
  const SceneWithLattices loaded = loadSceneWithLattices(request.scene, request.settings);
  const auto& defs = loaded.lattices;
  const auto it = std::find_if(defs.begin(), defs.end(), [&](const auto& d) { return d->name == request.name; });
  if (it == defs.end()) {
    std::string names;
    for (const auto& d : defs) names += (names.empty() ? "" : ", ") + d->name;
    throw Error(ErrorKind::Input, fmt::format("{}: no [[lattices]] entry named '{}' (defined: {})",
                                              request.scene.string(), request.name, names.empty() ? "none" : names));
  }
  return **it;
}

}  // namespace

BuiltTable buildLatticeTable(const LatticeDefinition& lattice, const TableSettings& settings) {
  try {
    const LatticeObject solid = sceneObject(lattice.object, lattice.objectText);
    const LhtPrecision requested = lattice.precisionUnder(settings);
    std::function<RasterAllowance(LazyRasterEstimate&)> admit;
    if (settings.admission)
      admit = [&](LazyRasterEstimate& estimate) {
        return settings.admission(lattice, estimate, lattice.formUnder(settings), requested);
      };
    return packTable(
        solid, lattice.lambda, lattice.oversample, settings, lattice.formUnder(settings),
        [&](std::uint64_t entries, std::uint64_t hitListBytes) {
          return settings.packing ? settings.packing(lattice, requested, entries, hitListBytes) : requested;
        },
        [&](LhtPrecision form) { return lattice.hashFor(form); }, admit);
  } catch (const Error& e) {
    throw Error(e.kind(), fmt::format("{}: lattice '{}': {}", lattice.origin, lattice.name, e.what()));
  }
}

BuiltTable buildLatticeTable(const TableRequest& request) {
  const bool fromScene = !request.scene.empty();
  if (fromScene == !request.shape.empty())
    throw Error(ErrorKind::Usage, "rasterize needs either --scene FILE --name NAME or --shape sphere|capsule");
  if (fromScene) {
    LatticeDefinition lattice = findDefinition(request);
    if (request.oversample) lattice.oversample = *request.oversample;  // the request overrides the scene
    return buildLatticeTable(lattice, request.settings);
  }
  const LatticeObject object = shapeObject(request);
  const LhtPrecision form = request.settings.precision.value_or(LhtPrecision::Thesis);
  return packTable(
      object, 1.0, request.oversample.value_or(1.0), request.settings, request.settings.form.value_or(LhtForm::Hashed),
      [&](std::uint64_t, std::uint64_t) { return form; }, [&](LhtPrecision) { return object.hash(); });
}

}  // namespace lattice::lht

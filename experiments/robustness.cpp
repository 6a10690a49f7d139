// The measurements of the robustness suite (experiments/robustness.sh):
// Tierny et al. 2006 claim invariance to rotation, translation and scale
// (sections 4.1.1 and 5.3), robustness to pose and to mesh sampling
// (section 4.1.2, figure 5; section 5.3, figures 9 and 11), stability within
// a class (section 5.3), and give timings (section 5.1). Each subcommand writes one or two CSV tables into
// OUT_DIR; tools/figures/robustness_report.py turns them into the report.
//
//   robustness rigid OUT_DIR SHREC_DIR CLA [SIMILARITIES]   rigid.csv, shrec_meshes.csv, shrec_pairs.csv
//   robustness sampling OUT_DIR GROUP MESH_OR_LIST...       sampling_GROUP.csv
//   robustness shrec-sample OUT_DIR SHREC_DIR CLA PER_CLASS sampling_shrec07.csv (the first PER_CLASS of each class)
//   robustness tosca OUT_DIR TOSCA_DIR                      tosca_poses.csv, tosca_pairs.csv
//   robustness timing OUT_DIR MESH FACES...                 timing.csv
//
// Feature-point repeatability, the share of the original's feature points
// with a variant point within epsilon x diameter once the variant's points
// are mapped to the original (MeshVariant::original_vertex), and the reverse
// share, is measured with fast-marching distances on the original whichever
// method found the points (one yardstick); epsilon = 0.05, the paper's.
// Every variant and every TOSCA pose is analysed with its vertices numbered
// anew (numbered_anew), as an independent file of the surface would be.
#include "batch_failures.h"
#include "reebkit/collection/mesh_inputs.h"
#include "reebkit/core/error.h"
#include "reebkit/core/timer.h"
#include "reebkit/deform/perturbation.h"
#include "reebkit/deform/pose.h"
#include "reebkit/geodesic/fast_marching.h"
#include "reebkit/io/psb_classes.h"
#include "reebkit/io/vts.h"
#include "reebkit/matching/graph_matching.h"
#include "reebkit/mesh/decimation.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/mesh/remeshing.h"
#include "reebkit/mesh/resampling.h"
#include "reebkit/mesh/transform.h"
#include "reebkit/pipeline/analysis_options.h"
#include "reebkit/pipeline/mesh_record.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace {

using namespace reebkit;
namespace fs = std::filesystem;

constexpr Geodesic kMethods[] = {Geodesic::Dijkstra, Geodesic::FastMarching};
constexpr double kEpsilon = 0.05;

/// The analysis options every measurement starts from: the defaults, or as
/// changed by --option NAME=VALUE.
AnalysisOptions base_options;

AnalysisOptions options_for(Geodesic method) {
  AnalysisOptions options = base_options;
  options.features.geodesic = method;
  return options;
}

/// An analysis and its attributed graph.
struct Analysed {
  MeshAnalysis analysis;
  GraphRecord record;
};

Analysed analyse(Mesh mesh, Geodesic method) {
  Analysed a{analyze_mesh(std::move(mesh), options_for(method)), {}};
  a.record = make_graph_record(a.analysis, compute_attributes(a.analysis));
  return a;
}

/// The feature points of an analysis on vertices of the mesh as given (not
/// on vertices added to fill holes).
std::vector<Index> surface_features(const MeshAnalysis& a) {
  std::vector<Index> out;
  const Index n = original_vertex_count(a.mesh);
  for (const Index v : a.features.vertices)
    if (v < n) out.push_back(v);
  return out;
}

/// Share of `points` with one of `others` within `radius` on `graph` (1 when `points` is empty).
double share_within(const MeshGraph& graph, const std::vector<Index>& points, const std::vector<Index>& others,
                    double radius) {
  if (points.empty()) return 1.0;
  if (others.empty()) return 0.0;
  const DistanceField d = fast_marching(graph, others, GeodesicOptions{radius});
  const auto near = std::count_if(points.begin(), points.end(),
                                  [&](Index v) { return d.distance[static_cast<std::size_t>(v)] <= radius; });
  return static_cast<double>(near) / static_cast<double>(points.size());
}

/// The variant's feature points as vertices of the original.
std::vector<Index> mapped_features(const MeshAnalysis& variant, const std::vector<Index>& original_vertex) {
  std::vector<Index> out;
  for (const Index v : surface_features(variant)) out.push_back(original_vertex[static_cast<std::size_t>(v)]);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<Index> sorted(std::vector<Index> v) {
  std::sort(v.begin(), v.end());
  return v;
}

/// One perturbation of the sampling section: its kind and strength.
struct SamplingPerturbation {
  std::string kind;
  double strength = 0;
};

const std::vector<SamplingPerturbation>& perturbations() {
  static const std::vector<SamplingPerturbation> all = {{"decimate", 0.75}, {"decimate", 0.5}, {"decimate", 0.25},
                                                        {"remesh", 0.5},    {"remesh", 1.0},   {"remesh", 2.0},
                                                        {"subdivide", 1},   {"noise", 0.001},  {"noise", 0.0025},
                                                        {"noise", 0.005},   {"noise", 0.01},   {"pose", 1},
                                                        {"pose", 2}};
  return all;
}

/// A seed of its own for each name (FNV-1a of its bytes).
std::uint64_t name_seed(const std::string& name) {
  std::uint64_t h = 1469598103934665603ull;
  for (const char c : name) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  return h;
}

/// The inverse of the permutation `to`.
std::vector<Index> inverse(const std::vector<Index>& to) {
  std::vector<Index> from(to.size());
  for (std::size_t v = 0; v < to.size(); ++v) from[static_cast<std::size_t>(to[v])] = static_cast<Index>(v);
  return from;
}

/// `variant` with its vertices numbered anew (random_permutation of `seed`),
/// as another file of the same surface would number them: a decimation, a
/// remeshing or a noise keeps the numbering of the original (vertex 0 where
/// it was), which an analysis that leans on the numbering would find far
/// more repeatable than a new scan.
MeshVariant numbered_anew(MeshVariant variant, std::uint64_t seed) {
  const std::vector<Index> to = random_permutation(variant.mesh.num_vertices(), seed);
  std::vector<Index> original(variant.original_vertex.size());
  for (std::size_t v = 0; v < to.size(); ++v) original[static_cast<std::size_t>(to[v])] = variant.original_vertex[v];
  variant.mesh = renumbered(variant.mesh, to);
  variant.original_vertex = std::move(original);
  return variant;
}

/// The perturbation applied to `mesh` (perturb_mesh; the pose is planned on
/// `analysis`, the analysis of `mesh`; remesh's strength is the vertex count
/// as a share of the mesh's).
MeshVariant perturb(const Mesh& mesh, const MeshAnalysis& analysis, const SamplingPerturbation& p) {
  using K = PerturbationKind;
  const K kind = p.kind == "decimate"    ? K::Decimate
                 : p.kind == "remesh"    ? K::Remesh
                 : p.kind == "subdivide" ? K::Subdivide
                 : p.kind == "noise"     ? K::Noise
                                         : K::Pose;
  reebkit::Perturbation step{kind, p.strength, {}, kind == K::Pose ? static_cast<std::uint64_t>(p.strength) : 1, {}};
  step.remesh.target_vertices = static_cast<Index>(std::lround(p.strength * mesh.num_vertices()));
  return perturb_mesh(mesh, step, &analysis);
}

struct VariantRow {
  std::string mesh;
  Geodesic method = Geodesic::Dijkstra;
  SamplingPerturbation perturbation;
  Index vertices = 0, variant_vertices = 0;
  std::size_t features = 0, variant_features = 0;
  double forward = 0, backward = 0;
  Index nodes = 0, variant_nodes = 0, leaves = 0, variant_leaves = 0, cycles = 0, variant_cycles = 0;
  double distance = 0;
  GraphRecord record;  // the variant's, for its rank among the originals
  int rank = 0;
  double seconds = 0;
};

/// Every perturbation of one mesh, with both methods.
std::vector<VariantRow> sample_mesh(const std::string& name, const Mesh& mesh, std::vector<GraphRecord>& originals) {
  std::array<Analysed, 2> original;
  for (std::size_t m = 0; m < 2; ++m) {
    original[m] = analyse(mesh, kMethods[m]);
    originals[m] = original[m].record;
  }
  std::vector<VariantRow> rows;
  // Each variant is made once (the pose planned on the Dijkstra analysis,
  // the default) and analysed with both methods.
  for (const SamplingPerturbation& p : perturbations()) {
    Timer timer;
    MeshVariant variant;
    std::string error;
    try {
      variant = numbered_anew(perturb(mesh, original[0].analysis, p),
                              name_seed(name + " " + p.kind + " " + std::to_string(p.strength)));
    } catch (const std::exception& e) {
      error = e.what();
    }
    const double made = timer.lap() / 1000.0;
    for (std::size_t m = 0; m < 2; ++m) {
      const MeshAnalysis& a = original[m].analysis;
      VariantRow row;
      row.mesh = name;
      row.method = kMethods[m];
      row.perturbation = p;
      try {
        if (!error.empty()) throw Error(error);
        const Analysed b = analyse(variant.mesh, kMethods[m]);
        const std::vector<Index> features = surface_features(a),
                                 mapped = mapped_features(b.analysis, variant.original_vertex);
        const double radius = kEpsilon * a.features.diameter;
        row.vertices = mesh.num_vertices();
        row.variant_vertices = variant.mesh.num_vertices();
        row.features = features.size();
        row.variant_features = surface_features(b.analysis).size();
        row.forward = share_within(a.graph, features, mapped, radius);
        row.backward = share_within(a.graph, mapped, features, radius);
        row.nodes = a.reeb.num_nodes();
        row.variant_nodes = b.analysis.reeb.num_nodes();
        row.leaves = a.reeb.leaf_count();
        row.variant_leaves = b.analysis.reeb.leaf_count();
        row.cycles = a.reeb.independent_cycles();
        row.variant_cycles = b.analysis.reeb.independent_cycles();
        row.distance = match_graphs(b.record, original[m].record).distance;
        row.record = b.record;
      } catch (const std::exception& e) {
        std::cerr << "robustness: " << name << " " << p.kind << " " << p.strength << ": " << e.what() << "\n";
        row.rank = -1;
      }
      row.seconds = made + timer.lap() / 1000.0;  // making the variant, counted for both methods
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

/// Runs sample_mesh on every mesh (in parallel), ranks each variant among
/// the group's originals (same method) and writes the table.
int write_sampling(const fs::path& out, const std::vector<std::pair<std::string, fs::path>>& meshes) {
  const auto n = static_cast<std::ptrdiff_t>(meshes.size());
  BatchFailures failures("robustness sampling");
  std::vector<std::vector<VariantRow>> rows(meshes.size());
  std::vector<std::vector<GraphRecord>> originals(meshes.size(), std::vector<GraphRecord>(2));
#pragma omp parallel for schedule(dynamic, 1)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    try {
      rows[k] = sample_mesh(meshes[k].first, load_mesh(meshes[k].second).components.front(), originals[k]);
    } catch (const std::exception& e) {
      failures.add(e.what(), meshes[k].second.string());
    }
#pragma omp critical
    std::cerr << "  " << meshes[k].first << " done\n";
  }
  std::ofstream csv(out);
  csv << "mesh,method,kind,strength,vertices,variant_vertices,features,variant_features,forward,backward,nodes,"
         "variant_nodes,leaves,variant_leaves,cycles,variant_cycles,distance,rank,seconds\n";
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (VariantRow& row : rows[i]) {
      const std::size_t m = row.method == Geodesic::Dijkstra ? 0 : 1;
      if (row.rank == 0) {
        const double own = match_graphs(row.record, originals[i][m]).distance;
        row.rank = 1;
        for (std::size_t j = 0; j < rows.size(); ++j)
          if (j != i && originals[j][m].ok && match_graphs(row.record, originals[j][m]).distance < own) ++row.rank;
      }
      char line[512];
      std::snprintf(line, sizeof line, "%s,%s,%s,%g,%d,%d,%zu,%zu,%.4f,%.4f,%d,%d,%d,%d,%d,%d,%.6g,%d,%.3f\n",
                    row.mesh.c_str(), geodesic_name(row.method), row.perturbation.kind.c_str(),
                    row.perturbation.strength, row.vertices, row.variant_vertices, row.features, row.variant_features,
                    row.forward, row.backward, row.nodes, row.variant_nodes, row.leaves, row.variant_leaves, row.cycles,
                    row.variant_cycles, row.distance, row.rank, row.seconds);
      csv << line;
    }
  if (!csv) throw Error(out.string() + ": cannot write the table");
  return failures.finish(meshes.size());
}

std::vector<std::pair<std::string, fs::path>> shrec_models(const fs::path& dir, const fs::path& cla,
                                                           std::size_t per_class) {
  std::vector<std::pair<std::string, fs::path>> out;
  for (const PsbClass& c : read_psb_classes(cla))
    for (std::size_t i = 0; i < std::min(per_class, c.models.size()); ++i)
      out.emplace_back(c.name + "/" + c.models[i], dir / (c.models[i] + ".off"));
  return out;
}

/// Section 1 (rigid + scale), 4 (classes) and 5 (hand-picked points) on every SHREC07 mesh.
int rigid(const fs::path& out, const fs::path& dir, const fs::path& cla, int similarities) {
  const std::vector<std::pair<std::string, fs::path>> models = shrec_models(dir, cla, 1000);
  const auto n = static_cast<std::ptrdiff_t>(models.size());
  std::vector<std::string> rigid_rows(models.size()), mesh_rows(models.size());
  std::vector<GraphRecord> records(models.size());
  BatchFailures failures("robustness rigid");
  std::vector<char> described(models.size(), 0);
#pragma omp parallel for schedule(dynamic, 1)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const std::string& name = models[k].first;
    try {  // an exception may not leave the parallel loop
      const Mesh mesh = load_mesh(models[k].second).components.front();
      const Geodesic method = base_options.features.geodesic;  // the default, fast marching
      const Analysed a = analyse(mesh, method);
      records[k] = a.record;
      std::string rows;
      for (int s = 1; s <= similarities; ++s) {
        const Similarity similarity = random_similarity(mesh, static_cast<std::uint64_t>(s));
        const Analysed b = analyse(transformed(mesh, similarity), method);
        double attribute = 0;  // largest difference of a node or edge attribute or signature entry
        const bool same_shape = b.record.node_attributes.size() == a.record.node_attributes.size() &&
                                b.record.edge_attributes.size() == a.record.edge_attributes.size();
        if (same_shape) {
          for (std::size_t j = 0; j < a.record.node_attributes.size(); ++j)
            attribute = std::max(attribute, std::abs(a.record.node_attributes[j] - b.record.node_attributes[j]));
          for (std::size_t j = 0; j < a.record.edge_attributes.size(); ++j)
            attribute = std::max(attribute, std::abs(a.record.edge_attributes[j] - b.record.edge_attributes[j]));
          for (std::size_t j = 0; j < a.record.signature.size(); ++j)
            attribute = std::max(attribute, std::abs(a.record.signature[j] - b.record.signature[j]));
        }
        const FeaturePoints &fa = a.analysis.features, &fb = b.analysis.features;
        char line[256];
        std::snprintf(line, sizeof line, "%s,%d,%.6f,%d,%d,%zu,%zu,%zu,%zu,%d,%d,%d,%.3g\n", name.c_str(), s,
                      similarity.scale, sorted({fa.source1, fa.source2}) == sorted({fb.source1, fb.source2}) ? 1 : 0,
                      sorted(fa.extrema1) == sorted(fb.extrema1) && sorted(fa.extrema2) == sorted(fb.extrema2) ? 1 : 0,
                      fa.extrema1.size(), fb.extrema1.size(), fa.extrema2.size(), fb.extrema2.size(),
                      sorted(b.analysis.features.vertices) == sorted(a.analysis.features.vertices) ? 1 : 0,
                      b.analysis.reeb.edges == a.analysis.reeb.edges &&
                              b.analysis.reeb.vertex_node == a.analysis.reeb.vertex_node
                          ? 1
                          : 0,
                      same_shape ? 1 : 0, same_shape ? attribute : -1.0);
        rows += line;
      }
      rigid_rows[k] = rows;
      // Hand-picked points against ours (file vertex ids), within 0.05 and 0.10 of the diameter.
      const fs::path vts = models[k].second.parent_path() / "features" / (models[k].second.stem().string() + ".vts");
      std::vector<Index> hand;
      {
        std::map<Index, Index> file_to_mesh;
        for (Index v = 0; v < a.analysis.mesh.num_vertices(); ++v)
          if (a.analysis.mesh.source_index(v) != kInvalidIndex) file_to_mesh[a.analysis.mesh.source_index(v)] = v;
        for (const Index id : fs::exists(vts) ? read_vts(vts) : std::vector<Index>{}) {  // not every model has one
          const auto it = file_to_mesh.find(id);
          if (it != file_to_mesh.end()) hand.push_back(it->second);
        }
      }
      const std::vector<Index> ours = surface_features(a.analysis);
      const double diameter = a.analysis.features.diameter;
      FeatureOptions dijkstra_features = base_options.features;
      dijkstra_features.geodesic = Geodesic::Dijkstra;
      const std::size_t dijkstra_count =
          extract_feature_points(a.analysis.mesh, a.analysis.graph, dijkstra_features).vertices.size();
      char line[512];
      std::snprintf(line, sizeof line, "%s,%d,%d,%d,%zu,%zu,%zu,%.4f,%.4f,%.4f,%.4f\n", name.c_str(),
                    a.analysis.reeb.num_nodes(), a.analysis.reeb.leaf_count(), a.analysis.reeb.independent_cycles(),
                    ours.size(), dijkstra_count, hand.size(),
                    share_within(a.analysis.graph, ours, hand, 0.05 * diameter),
                    share_within(a.analysis.graph, hand, ours, 0.05 * diameter),
                    share_within(a.analysis.graph, ours, hand, 0.10 * diameter),
                    share_within(a.analysis.graph, hand, ours, 0.10 * diameter));
      mesh_rows[k] = line;
      described[k] = 1;
    } catch (const std::exception& e) {
      rigid_rows[k].clear();
      failures.add(e.what(), models[k].second.string());
    }
  }
  std::ofstream r(out / "rigid.csv"), m(out / "shrec_meshes.csv"), p(out / "shrec_pairs.csv");
  r << "mesh,similarity,scale,same_diameter_ends,same_extrema,extrema1,variant_extrema1,extrema2,variant_extrema2,"
       "same_features,same_graph,same_attribute_shape,max_attribute_difference\n";
  m << "mesh,nodes,leaves,cycles,features,features_dijkstra,handpicked,precision05,recall05,precision10,recall10\n";
  for (std::size_t k = 0; k < models.size(); ++k) r << rigid_rows[k], m << mesh_rows[k];
  p << "a,b,distance\n";
  const std::vector<MatchableGraph> graphs = make_matchable_graphs(records);
  std::vector<std::string> pair_rows(models.size());
#pragma omp parallel for schedule(dynamic, 4)
  for (std::ptrdiff_t i = 0; i < n; ++i)
    for (std::ptrdiff_t j = i + 1; j < n; ++j) {
      if (!described[static_cast<std::size_t>(i)] || !described[static_cast<std::size_t>(j)]) continue;
      char line[128];
      std::snprintf(line, sizeof line, "%td,%td,%.6g\n", i, j,
                    match_graphs(graphs[static_cast<std::size_t>(i)], graphs[static_cast<std::size_t>(j)]).distance);
      pair_rows[static_cast<std::size_t>(i)] += line;
    }
  for (const std::string& rows : pair_rows) p << rows;
  if (!r || !m || !p) throw Error(out.string() + ": cannot write the SHREC07 tables");
  return failures.finish(models.size());
}

/// "michael12" -> "michael".
std::string pose_class(std::string stem) {
  while (!stem.empty() && std::isdigit(static_cast<unsigned char>(stem.back()))) stem.pop_back();
  return stem;
}

/// Section 3: each TOSCA pose against the first pose of its class (same
/// triangulation: vertex i corresponds, each pose numbered anew), both
/// methods; all pairs of graph distances.
int tosca(const fs::path& out, const fs::path& dir) {
  const std::vector<MeshInput> all = list_mesh_inputs({dir.string()});
  const auto n = static_cast<std::ptrdiff_t>(all.size());
  std::vector<std::array<Analysed, 2>> analysed_all(all.size());
  // Each pose numbered anew (numbered_anew): the poses share the numbering
  // of their files, vertex i corresponding, which an analysis must not lean on.
  std::vector<std::vector<Index>> to_all(all.size());
  BatchFailures failures("robustness tosca");
  std::vector<char> described(all.size(), 0);
#pragma omp parallel for schedule(dynamic, 1)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    try {  // an exception may not leave the parallel loop
      const Mesh mesh = load_mesh(all[k].path).components.front();
      to_all[k] = random_permutation(mesh.num_vertices(), name_seed(all[k].path.stem().string()));
      const Mesh anew = renumbered(mesh, to_all[k]);
      for (std::size_t m = 0; m < 2; ++m) analysed_all[k][m] = analyse(anew, kMethods[m]);
      described[k] = 1;
    } catch (const std::exception& e) {
      failures.add(e.what(), all[k].path.string());
    }
  }
  std::vector<MeshInput> inputs;  // the meshes described, in order
  std::vector<std::array<Analysed, 2>> analysed;
  std::vector<std::vector<Index>> to, from;  // file vertex -> analysed vertex, and back
  for (std::size_t k = 0; k < all.size(); ++k)
    if (described[k]) {
      inputs.push_back(all[k]), analysed.push_back(std::move(analysed_all[k]));
      from.push_back(inverse(to_all[k]));
      to.push_back(std::move(to_all[k]));
    }
  std::ofstream poses(out / "tosca_poses.csv"), pairs(out / "tosca_pairs.csv");
  poses << "mesh,class,reference,method,features,reference_features,forward,backward,nodes,reference_nodes,leaves,"
           "reference_leaves,distance\n";
  std::map<std::string, std::size_t> reference;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const std::string stem = inputs[i].path.stem().string(), label = pose_class(stem);
    const auto [it, first] = reference.try_emplace(label, i);
    if (first) continue;
    for (std::size_t m = 0; m < 2; ++m) {
      const MeshAnalysis& a = analysed[it->second][m].analysis;
      const MeshAnalysis& b = analysed[i][m].analysis;
      const std::vector<Index> fa = surface_features(a);
      std::vector<Index> fb;  // on the reference's numbering
      for (const Index v : surface_features(b))
        fb.push_back(to[it->second][static_cast<std::size_t>(from[i][static_cast<std::size_t>(v)])]);
      const double radius = kEpsilon * a.features.diameter;
      char line[512];
      std::snprintf(line, sizeof line, "%s,%s,%s,%s,%zu,%zu,%.4f,%.4f,%d,%d,%d,%d,%.6g\n", stem.c_str(), label.c_str(),
                    inputs[it->second].path.stem().string().c_str(), geodesic_name(kMethods[m]), fb.size(), fa.size(),
                    share_within(a.graph, fa, fb, radius), share_within(a.graph, fb, fa, radius), b.reeb.num_nodes(),
                    a.reeb.num_nodes(), b.reeb.leaf_count(), a.reeb.leaf_count(),
                    match_graphs(analysed[i][m].record, analysed[it->second][m].record).distance);
      poses << line;
    }
  }
  pairs << "a,b,class_a,class_b,method,distance\n";
  for (std::size_t m = 0; m < 2; ++m)
    for (std::size_t i = 0; i < inputs.size(); ++i)
      for (std::size_t j = i + 1; j < inputs.size(); ++j)
        pairs << inputs[i].path.stem().string() << "," << inputs[j].path.stem().string() << ","
              << pose_class(inputs[i].path.stem().string()) << "," << pose_class(inputs[j].path.stem().string()) << ","
              << geodesic_name(kMethods[m]) << ","
              << match_graphs(analysed[i][m].record, analysed[j][m].record).distance << "\n";
  if (!poses || !pairs) throw Error(out.string() + ": cannot write the TOSCA tables");
  return failures.finish(all.size());
}

/// Section 6: the pipeline's time on `mesh` decimated to each face count
/// (subdivided first when it has fewer faces than asked), median of 3 runs.
void timing(const fs::path& out, const fs::path& path, const std::vector<Index>& faces) {
  const Mesh mesh = load_mesh(path).components.front();
  std::ofstream csv(out / "timing.csv");
  csv << "mesh,target_faces,faces,vertices,method,graph_ms,features_ms,quotient_ms,reeb_ms,total_ms\n";
  for (const Index target : faces) {
    Mesh sized = mesh;
    while (sized.num_triangles() < target) sized = subdivide_mesh(sized, 1).mesh;
    sized = decimate_mesh(sized,
                          DecimationOptions{std::min(1.0, static_cast<double>(target) / sized.num_triangles()), 0.02})
                .mesh;
    for (const Geodesic method : kMethods) {
      std::vector<AnalysisTimings> runs;
      for (int run = 0; run < 3; ++run) runs.push_back(analyze_mesh(sized, options_for(method)).timings);
      std::sort(runs.begin(), runs.end(),
                [](const AnalysisTimings& a, const AnalysisTimings& b) { return a.total() < b.total(); });
      const AnalysisTimings& t = runs[1];
      char line[256];
      std::snprintf(line, sizeof line, "%s,%d,%d,%d,%s,%.2f,%.2f,%.2f,%.2f,%.2f\n", path.stem().string().c_str(),
                    target, sized.num_triangles(), sized.num_vertices(), geodesic_name(method), t.graph, t.features,
                    t.quotient, t.reeb, t.total());
      csv << line;
    }
  }
  if (!csv) throw Error(out.string() + ": cannot write timing.csv");
}

}  // namespace

/// Sets the analysis option of `text` "NAME=VALUE" in base_options.
void set_base_option(const std::string& text) { set_option_text(analysis_option_fields(), base_options, text); }

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) args.push_back("");
  const auto usage = [] {
    std::cerr << "usage: robustness [--option NAME=VALUE]... SUBCOMMAND ...\n"
                 "       robustness rigid OUT_DIR SHREC_DIR CLA [SIMILARITIES]\n"
                 "       robustness sampling OUT_DIR GROUP MESH_OR_LIST...\n"
                 "       robustness shrec-sample OUT_DIR SHREC_DIR CLA PER_CLASS\n"
                 "       robustness tosca OUT_DIR TOSCA_DIR\n"
                 "       robustness timing OUT_DIR MESH FACES...\n";
    return 2;
  };
  try {
    while (args.size() >= 2 && args[0] == "--option") {
      set_base_option(args[1]);
      args.erase(args.begin(), args.begin() + 2);
    }
    if (args.size() < 3) return usage();
    Timer timer;
    int status = 0;  // 1 when every mesh failed
    const fs::path out = args[1];
    fs::create_directories(out);
    if (args[0] == "rigid" && args.size() >= 4) {
      status = rigid(out, args[2], args[3], args.size() > 4 ? std::stoi(args[4]) : 3);
    } else if (args[0] == "sampling" && args.size() >= 4) {
      std::vector<std::pair<std::string, fs::path>> meshes;
      for (const MeshInput& input : list_mesh_inputs(std::vector<std::string>(args.begin() + 3, args.end())))
        meshes.emplace_back(input.path.stem().string(), input.path);
      status = write_sampling(out / ("sampling_" + args[2] + ".csv"), meshes);
    } else if (args[0] == "shrec-sample" && args.size() == 5) {
      status = write_sampling(out / "sampling_shrec07.csv", shrec_models(args[2], args[3], std::stoul(args[4])));
    } else if (args[0] == "tosca") {
      status = tosca(out, args[2]);
    } else if (args[0] == "timing" && args.size() >= 4) {
      std::vector<Index> faces;
      for (std::size_t i = 3; i < args.size(); ++i) faces.push_back(static_cast<Index>(std::stol(args[i])));
      timing(out, args[2], faces);
    } else {
      return usage();
    }
    std::cerr << "robustness " << args[0] << ": " << timer.lap() / 1000.0 << " s\n";
    return status;
  } catch (const std::exception& e) {
    std::cerr << "robustness " << args[0] << ": " << e.what() << "\n";
    return 1;
  }
  return 0;
}

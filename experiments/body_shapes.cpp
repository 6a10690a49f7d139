// Synthetic people for retrieval by body shape (the body-shape collection of
// experiments/pose_retrieval.sh): one TOSCA body in its poses (michael0 ..
// michael19 share one vertex numbering) given different proportions with
// deform/proportions.h, the same person in every pose.
//
// The parts are planned once on the first pose (the lowest number), with
// the analysis options given (--option NAME=VALUE, the table of
// pipeline/analysis_options.h; pose_retrieval.sh pins them): its
// limbs, the smallest components of the Reeb graph holding at least 5 % of
// the surface (michael: both legs, both arms, the head with the top of the
// chest), and its torso, the largest region in no limb. A person changes 2
// to 4 different parts, each by a factor drawn uniformly in FACTORS (default
// [1.05, 1.15]): a
// limb longer (ProportionOptions::scale s with thickness 1 / s) or thicker
// (thickness s), the torso thicker; no two people change the same parts the
// same ways. Each person is shown in POSES poses drawn from all of them.
//
//   build/experiments/body_shapes [--option NAME=VALUE]... TOSCA_DIR OUT_DIR [--shape michael]
//       [--people 10] [--poses 10] [--factors 1.05:1.15] [--seed 1] [--cla FILE]
//
// Writes OUT_DIR/personNN_SHAPEK.ply (binary PLY, the pose's vertices and
// triangles moved), OUT_DIR/people.txt (each person's changes and poses) and
// the PSB class file FILE (default OUT_DIR/body-shape.cla; class = person).
#include "reebkit/core/error.h"
#include "reebkit/core/timer.h"
#include "reebkit/deform/proportions.h"
#include "reebkit/io/mesh_io.h"
#include "reebkit/mesh/hole_filling.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/pipeline/analysis_options.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;
using reebkit::Index;

constexpr double kMinLimbShare = 0.05;  // a limb holds at least this share of the surface
constexpr int kMinChanges = 2, kMaxChanges = 4;

struct Part {
  Index node;
  bool limb;     ///< a component (else the torso region)
  double share;  ///< of the surface area
};

struct Change {
  std::size_t part;  ///< into the part list
  bool longer;       ///< else thicker
  double factor;
};

struct Person {
  std::string name;
  std::vector<Change> changes;
  std::vector<std::size_t> poses;  ///< into the pose list, ascending
};

/// The limbs (smallest components of at least kMinLimbShare of the area) and
/// the torso (the largest region in none of them).
std::vector<Part> body_parts(const reebkit::ReebGraph& g) {
  const std::size_t n = g.nodes.size();
  std::vector<std::vector<Index>> children(n);
  std::vector<char> has_parent(n, 0);
  for (const auto& [from, to] : g.edges) {
    children[static_cast<std::size_t>(from)].push_back(to);
    has_parent[static_cast<std::size_t>(to)] = 1;
  }
  double total = 0.0;
  for (const reebkit::ReebNode& node : g.nodes) total += node.area;
  // Component areas, children before parents (edges go to later nodes).
  std::vector<double> area(n, 0.0);
  std::vector<char> holds_limb(n, 0);
  std::vector<Part> parts;
  for (std::size_t i = n; i-- > 0;) {
    area[i] = g.nodes[i].area;
    for (const Index c : children[i]) {
      area[i] += area[static_cast<std::size_t>(c)];
      holds_limb[i] = holds_limb[i] || holds_limb[static_cast<std::size_t>(c)];
    }
    if (has_parent[i] && !holds_limb[i] && area[i] >= kMinLimbShare * total) {
      parts.push_back({static_cast<Index>(i), true, area[i] / total});
      holds_limb[i] = 1;
    }
  }
  // A node is in a limb when a parent is a limb or in one.
  std::vector<char> in_limb(n, 0);
  for (const Part& p : parts) in_limb[static_cast<std::size_t>(p.node)] = 1;
  for (const auto& [from, to] : g.edges)
    if (in_limb[static_cast<std::size_t>(from)]) in_limb[static_cast<std::size_t>(to)] = 1;
  Index torso = reebkit::kInvalidIndex;
  for (std::size_t i = 0; i < n; ++i)
    if (!in_limb[i] &&
        (torso == reebkit::kInvalidIndex || g.nodes[i].area > g.nodes[static_cast<std::size_t>(torso)].area))
      torso = static_cast<Index>(i);
  std::reverse(parts.begin(), parts.end());
  if (torso != reebkit::kInvalidIndex)
    parts.push_back({torso, false, g.nodes[static_cast<std::size_t>(torso)].area / total});
  return parts;
}

/// The poses of `shape` in `dir` (SHAPE<number>.off), by number.
std::vector<fs::path> pose_files(const fs::path& dir, const std::string& shape) {
  const std::regex name(shape + "([0-9]+)\\.off");
  std::vector<std::pair<int, fs::path>> found;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    std::smatch m;
    const std::string file = e.path().filename().string();
    if (std::regex_match(file, m, name)) found.emplace_back(std::stoi(m[1]), e.path());
  }
  std::sort(found.begin(), found.end());
  std::vector<fs::path> out;
  for (auto& f : found) out.push_back(std::move(f.second));
  return out;
}

/// Factor range: the interval of the uniform draws.
struct Factors {
  double low = 1.05, high = 1.15;
};

std::vector<Person> draw_people(int people, int poses, std::size_t pose_count, std::size_t part_count, Factors factors,
                                std::uint64_t seed, const std::vector<Part>& parts) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> changes(kMinChanges, std::min<int>(kMaxChanges, static_cast<int>(part_count)));
  std::uniform_real_distribution<double> factor(factors.low, factors.high);
  std::bernoulli_distribution longer(0.5);
  std::set<std::vector<std::pair<std::size_t, bool>>> seen;
  std::vector<Person> out;
  while (static_cast<int>(out.size()) < people) {
    Person p;
    std::ostringstream name;
    name << "person" << std::setw(2) << std::setfill('0') << out.size() + 1;
    p.name = name.str();
    std::vector<std::size_t> order(part_count);
    for (std::size_t i = 0; i < part_count; ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), rng);
    order.resize(static_cast<std::size_t>(changes(rng)));
    std::sort(order.begin(), order.end());
    std::vector<std::pair<std::size_t, bool>> signature;
    for (const std::size_t part : order) {
      const bool make_longer = parts[part].limb && longer(rng);
      p.changes.push_back({part, make_longer, factor(rng)});
      signature.emplace_back(part, make_longer);
    }
    if (!seen.insert(signature).second) continue;  // the same changes as an earlier person: draw again
    std::vector<std::size_t> all(pose_count);
    for (std::size_t i = 0; i < pose_count; ++i) all[i] = i;
    std::shuffle(all.begin(), all.end(), rng);
    p.poses.assign(all.begin(), all.begin() + poses);
    std::sort(p.poses.begin(), p.poses.end());
    out.push_back(std::move(p));
  }
  return out;
}

/// `plan` restricted to the first n vertices: a plan of an analysis (whose
/// mesh has its small holes filled, the new vertices last) for the surface as
/// read from its file, the same in every pose whatever holes it has.
reebkit::ProportionPlan original_vertices_only(reebkit::ProportionPlan plan, Index n) {
  const auto size = static_cast<std::size_t>(n);
  plan.weight.resize(size);
  plan.level.resize(size);
  plan.position.resize(size);
  plan.anchor.erase(std::remove_if(plan.anchor.begin(), plan.anchor.end(), [n](Index v) { return v >= n; }),
                    plan.anchor.end());
  return plan;
}

reebkit::Mesh load(const fs::path& path) { return std::move(reebkit::load_mesh(path).components.front()); }

int run(const fs::path& tosca, const fs::path& out, const std::string& shape, int people, int poses, Factors factors,
        std::uint64_t seed, fs::path cla, const reebkit::AnalysisOptions& planning) {
  const std::vector<fs::path> files = pose_files(tosca, shape);
  if (files.empty()) throw reebkit::Error(tosca.string() + ": no " + shape + "<number>.off");
  if (people < 1 || poses < 1 || poses > static_cast<int>(files.size()))
    throw reebkit::InvalidArgument("--people must be >= 1 and --poses in [1, " + std::to_string(files.size()) + "]");
  if (!(factors.low > 0.0 && factors.low <= factors.high && std::isfinite(factors.high)))
    throw reebkit::InvalidArgument("--factors LOW:HIGH needs 0 < LOW <= HIGH");
  fs::create_directories(out);
  if (cla.empty()) cla = out / "body-shape.cla";
  reebkit::Timer timer;
  const reebkit::MeshAnalysis reference = reebkit::analyze_mesh(load(files.front()), planning);
  const std::vector<Part> parts = body_parts(reference.reeb);
  if (parts.size() < static_cast<std::size_t>(kMinChanges))
    throw reebkit::Error(files.front().string() + ": fewer than " + std::to_string(kMinChanges) + " body parts");
  std::vector<Person> persons = draw_people(people, poses, files.size(), parts.size(), factors, seed, parts);
  std::cerr << "body_shapes: " << files.front().string() << " analysed, " << parts.size() << " parts, "
            << timer.lap() / 1000.0 << " s\n";

  // The plans: one per change, planned on the reference.
  const Index vertices = reebkit::original_vertex_count(reference.mesh);
  std::vector<std::vector<reebkit::ProportionPlan>> plans(persons.size());
  for (std::size_t p = 0; p < persons.size(); ++p)
    for (const Change& c : persons[p].changes) {
      reebkit::ProportionOptions options;
      options.node = parts[c.part].node;
      options.part = parts[c.part].limb ? reebkit::ProportionPart::Component : reebkit::ProportionPart::Region;
      options.scale = c.longer ? c.factor : 1.0;
      options.thickness = c.longer ? 1.0 / c.factor : c.factor;
      plans[p].push_back(original_vertices_only(reebkit::plan_proportions(reference, options), vertices));
    }

  for (std::size_t k = 0; k < files.size(); ++k) {
    const reebkit::Mesh pose = load(files[k]);
    if (pose.num_vertices() != vertices)
      throw reebkit::Error(files[k].string() + ": " + std::to_string(pose.num_vertices()) + " vertices, " +
                           files.front().string() + " " + std::to_string(vertices) + ": not the same vertex numbering");
    for (std::size_t p = 0; p < persons.size(); ++p) {
      if (!std::binary_search(persons[p].poses.begin(), persons[p].poses.end(), k)) continue;
      reebkit::Mesh body = pose;
      for (const reebkit::ProportionPlan& plan : plans[p]) body = reebkit::apply_proportions(body, plan);
      reebkit::write_mesh(out / (persons[p].name + "_" + files[k].stem().string() + ".ply"), body);
    }
  }

  std::ofstream text(out / "people.txt");
  text << "# body_shapes " << tosca.string() << " (" << shape << ", factors " << factors.low << ":" << factors.high
       << ", seed " << seed << "): parts planned on " << files.front().filename().string() << "\n";
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const reebkit::ReebNode& node = reference.reeb.nodes[static_cast<std::size_t>(parts[i].node)];
    text << "# part " << i << ": " << (parts[i].limb ? "limb, component of node " : "torso, region of node ")
         << parts[i].node << ", " << std::fixed << std::setprecision(1) << 100.0 * parts[i].share
         << " % of the area, barycenter " << node.barycenter.transpose() << "\n";
  }
  std::ostringstream blocks;
  for (const Person& p : persons) {
    text << p.name << ":";
    for (const Change& c : p.changes)
      text << " part " << c.part << (c.longer ? " longer x" : " thicker x") << std::setprecision(3) << c.factor << ";";
    text << " poses";
    blocks << "\n" << p.name << " 0 " << p.poses.size() << "\n";
    for (const std::size_t k : p.poses) {
      text << " " << files[k].stem().string();
      blocks << p.name << "_" << files[k].stem().string() << "\n";
    }
    text << "\n";
  }
  std::ofstream(cla) << "PSB 1\n"
                     << persons.size() << " " << persons.size() * static_cast<std::size_t>(poses) << "\n"
                     << blocks.str();
  if (!text) throw reebkit::Error((out / "people.txt").string() + ": cannot write");
  std::cerr << "body_shapes: " << persons.size() * static_cast<std::size_t>(poses) << " meshes in " << out.string()
            << ", " << timer.lap() / 1000.0 << " s\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  const auto usage = [] {
    std::cerr << "usage: body_shapes [--option NAME=VALUE]... TOSCA_DIR OUT_DIR [--shape michael] [--people 10] "
                 "[--poses 10] [--factors 1.05:1.15] [--seed 1] [--cla FILE]\n";
    return 2;
  };
  reebkit::AnalysisOptions planning;
  try {
    while (args.size() >= 2 && args[0] == "--option") {
      reebkit::set_option_text(reebkit::analysis_option_fields(), planning, args[1]);
      args.erase(args.begin(), args.begin() + 2);
    }
  } catch (const std::exception& e) {
    std::cerr << "body_shapes: " << e.what() << "\n";
    return 2;
  }
  if (args.size() < 2 || args.size() % 2 != 0) return usage();
  std::map<std::string, std::string> options{{"--shape", "michael"},     {"--people", "10"}, {"--poses", "10"},
                                             {"--factors", "1.05:1.15"}, {"--seed", "1"},    {"--cla", ""}};
  for (std::size_t i = 2; i < args.size(); i += 2) {
    if (!options.count(args[i])) return usage();
    options[args[i]] = args[i + 1];
  }
  try {
    Factors factors;
    const std::string& range = options["--factors"];
    const std::size_t colon = range.find(':');
    if (colon == std::string::npos) return usage();
    factors.low = std::stod(range.substr(0, colon));
    factors.high = std::stod(range.substr(colon + 1));
    return run(args[0], args[1], options["--shape"], std::stoi(options["--people"]), std::stoi(options["--poses"]),
               factors, std::stoull(options["--seed"]), options["--cla"], planning);
  } catch (const std::exception& e) {
    std::cerr << "body_shapes: " << e.what() << "\n";
    return 1;
  }
}

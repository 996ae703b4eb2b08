#pragma once
// What a generator knows about an organ beyond its surface: the volumetric body inside its
// walls, the cavities the walls enclose, the valves between them and the landmarks a
// clinician measures. Only the anatomical heart has one (mesh/procedural/heart.cpp);
// surfaces from files have none.

#include <Eigen/Core>
#include <array>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace systole::mesh {

/// The muscle as particles through the walls (a hexahedral lattice laid along each wall:
/// around, along and across it) joined by springs, with the direction of the muscle fibres
/// each spring sees, and every surface vertex a fixed combination of particles.
struct Myocardium {
  std::vector<Eigen::Vector3d> nodes;  ///< unit: m
  std::vector<int> node_part;          ///< Per node: index into the mesh's part_names.
  std::vector<std::pair<int, int>> node_also_in;  ///< (node, part): other parts a node belongs to.
  std::vector<double> node_volume_m3;  ///< Per node: its share of the wall's volume. unit: m^3
  /// Per node: the wall it lies in (0 the left heart's, 1 the right heart's, then the
  /// vessels', in the order they were built), and where in it: along the meridian from the
  /// apex (0) to the far pole (1), and across the wall from the lining (0) to the outside (1).
  /// The conduction system (electro/conduction.h) finds the endocardium and the base by them.
  std::vector<int> node_wall;
  std::vector<double> node_along, node_depth;
  double annulus_along = 0;  ///< The atrioventricular annulus's place along the hearts' meridians. unit: 1
  std::vector<std::pair<int, int>> springs;
  /// Per spring: its share of the cells' volume over its rest length squared, divided by the
  /// mean, so a uniform material gives each spring the stiffness its cells need. unit: 1
  std::vector<double> spring_weight;
  /// Per spring: squared cosines of its direction with the fibre and with the wall's normal
  /// (the sheet normal), where it lies. A fibre share of -1 marks a spring without fibres
  /// (a vessel's, the glue between walls): driven, it shortens evenly like a surface spring. unit: 1
  std::vector<double> fibre_share, normal_share;
  /// Per spring: how much the cross-fibre direction in the wall shortens with the fibre (its
  /// share of the fibre's shortening). unit: 1
  std::vector<double> cross_fibre;
  /// Per surface vertex: up to 8 nodes and weights (summing to 1) it follows.
  std::vector<std::array<int, 8>> vertex_nodes;
  std::vector<std::array<double, 8>> vertex_weights;

  bool empty() const { return nodes.empty(); }
};

/// A cavity's lining (the endocardium), its triangles facing into the blood; its open edges
/// are the valve annuli, closed by flat caps when its volume is measured.
struct Cavity {
  std::string name;  ///< "left_ventricle", ...
  std::vector<Eigen::Vector3i> lining;
  /// The lining's open edge loops, each in the order its cap turns like the lining (find_rims).
  std::vector<std::vector<int>> rims;
};

/// Finds the cavity's rims: the directed edges its lining uses once, walked into loops.
void find_rims(Cavity& cavity);

/// A valve's leaflets: surface vertices that swing between their closed place (where the
/// surface has them) and their open place as blood flows through.
struct Valve {
  std::string name;       ///< "mitral_valve", ...
  std::string chamber;    ///< The ventricle whose volume decides it.
  bool opens_on_filling;  ///< Inflow valve (opens while the ventricle fills) or outflow (while it empties).
  std::vector<int> vertices;
  std::vector<Eigen::Vector3d> open_positions;  ///< Per vertex, at rest. unit: m
};

/// Surface vertices where the left ventricle's shape is measured (docs/anatomy.md).
struct VentricleLandmarks {
  int apex = -1;                          ///< Epicardial apex.
  std::vector<int> annulus;               ///< The mitral annulus (lining ring).
  std::vector<std::pair<int, int>> wall;  ///< Mid-ventricular (lining, epicardium) pairs across the wall.
  /// Per wall pair: its mid-ventricular segment of the American Heart Association's 17
  /// (Cerqueira et al. 2002, Circulation 105:539): 7 anterior, 8 anteroseptal, 9
  /// inferoseptal, 10 inferior, 11 inferolateral, 12 anterolateral, 60 deg each, the septum
  /// between 8 and 9.
  std::vector<int> wall_segment;
  std::vector<int> apical_ring, basal_ring;  ///< Epicardial rings for the twist.
};

struct Anatomy {
  Myocardium myocardium;
  /// The body's directions in the organ's coordinates, as columns: the patient's left, head
  /// and front (the generator's +X, +Y, +Z, turned by the scene's rotation). The ECG's
  /// electrodes sit on a torso placed about them (electro/leads.h).
  Eigen::Matrix3d body_axes = Eigen::Matrix3d::Identity();
  std::vector<Cavity> cavities;
  std::vector<Valve> valves;
  VentricleLandmarks left_ventricle;
  /// The chamber walls' surfaces (outside and lining), facing out of the muscle: they
  /// enclose the myocardium, whose volume shows how nearly incompressible it stays.
  std::vector<Eigen::Vector3i> muscle;
  /// Surface vertices inside the chamber walls' closed outside, which hides them from any
  /// eye outside the heart unless it is cut or see-through: the cavities' linings and the
  /// valves between atria and ventricles (the outflow valves, in the vessels, show through
  /// their open ends). A renderer may leave their triangles out of such views.
  std::vector<int> enclosed_vertices;

  bool empty() const { return myocardium.empty(); }
  /// The cavity named `name` ("left_ventricle", ...), or null.
  const Cavity* cavity(std::string_view name) const {
    for (const Cavity& c : cavities) {
      if (c.name == name) return &c;
    }
    return nullptr;
  }
};

/// The chamber walls' outside (the epicardium): the muscle's surface less the cavities'
/// linings, facing out; closed where each wall is (a wall's outside is one closed surface).
std::vector<Eigen::Vector3i> epicardium(const Anatomy& anatomy);

/// The cavities' lining vertices that are not also corners of the epicardium, sorted: the
/// vertices that must stay inside it (docs/anatomy.md, "The wall keeps its lining inside").
std::vector<int> lining_vertices(const Anatomy& anatomy);

/// Volume enclosed by a cavity's lining at `positions`, each rim closed by a fan about its
/// centroid. unit: m^3
double cavity_volume(const Cavity& cavity, const std::vector<Eigen::Vector3d>& positions);
double cavity_volume(const Cavity& cavity, const Eigen::Matrix3Xd& positions);

}  // namespace systole::mesh

// The physical tables of an organ: its soft body and the blood in its ventricles.

#include "scene/schema/parts.h"

namespace systole::scene::schema {
namespace {

/// `body.lattice`: a whole number of voxels, or `auto`.
ValueSpec<int> lattice_spec() {
  ValueSpec<int> spec = whole<int>(0, 64);
  spec.range = "0..64, or `auto`";
  spec.read = [read_number = spec.read](const Node& node, int& out, const std::string& path, const Context& ctx) {
    if (node.kind == Node::Kind::kScalar && node.scalar == "auto") {
      out = Body::kLatticeAuto;
      return;
    }
    read_number(node, out, path, ctx);
  };
  return spec;
}

}  // namespace

ValueSpec<Blood> blood_spec() {
  const auto pressure = [] { return quantity(Dimension::kPressure, closed(0, 1e6)); };
  return map<Blood>(
      {
          field("aortic_pressure", pressure(), &Blood::aortic_pressure_Pa,
                "The left ventricle's afterload: the aortic valve opens when the ventricle's pressure "
                "reaches it, and the ejecting ventricle pushes against it. On the body's own scale: its "
                "muscle's isovolumic pressure (docs/anatomy.md, \"Blood\")."),
          field("pulmonary_pressure", pressure(), &Blood::pulmonary_pressure_Pa,
                "The right ventricle's afterload, as aortic_pressure for the pulmonary valve."),
          field("aortic_elastance", quantity(Dimension::kElastance, closed(0, 1e12)), &Blood::aortic_elastance_Pa_per_m3,
                "How the aortic pressure rises as the left ventricle ejects, per volume ejected (Sunagawa's "
                "effective arterial elastance): the artery fills, so the valve shuts against a higher pressure "
                "than it opened at. 0 = a constant afterload."),
          field("pulmonary_elastance", quantity(Dimension::kElastance, closed(0, 1e12)), &Blood::pulmonary_elastance_Pa_per_m3,
                "The pulmonary artery's, as aortic_elastance for the right ventricle."),
          field("chordae", number(closed(0, 1)), &Blood::chordae,
                "The share of the shut mitral valve's load that its chordae tendineae carry to the papillary "
                "muscles (the left ventricle's anterolateral and inferior mid-wall), pulling the wall towards "
                "the base; the rest pushes the annulus towards the atrium. 0 = all on the annulus."),
          field("filling_pressure", pressure(), &Blood::filling_pressure_Pa,
                "The atria's pressure: an inflow valve (mitral, tricuspid) opens when its relaxing "
                "ventricle's pressure falls below it, and the filling ventricle is pushed out with it."),
      },
      [](const Node&, Blood& b, const std::string&, const Context&) { b.enabled = true; });
}

ValueSpec<Body> body_spec() {
  return map<Body>({
      field("mass", quantity(Dimension::kMass, open_closed(0, 1000)), &Body::mass_kg,
            "Total mass, spread over vertices by area."),
      field("stiffness", quantity(Dimension::kStiffness, open_closed(0, 1e9)), &Body::stiffness_N_per_m,
            "Spring stiffness of each surface edge."),
      field("damping", quantity(Dimension::kTime, closed(0, 1)), &Body::damping_s,
            "Stiffness-proportional damping time: each spring damps the whole relative velocity of its "
            "ends with c = k damping (docs/accuracy.md)."),
      field("volume_stiffness", quantity(Dimension::kPressure, closed(0, 1e9)), &Body::volume_stiffness_Pa,
            "Bulk modulus of the enclosed volume; 0 = no volume constraint."),
      field("drag", quantity(Dimension::kRate, closed(0, 1000)), &Body::drag_per_s,
            "Velocity damping towards rest (the surrounding tissue)."),
      field("bending", quantity(Dimension::kStiffness, closed(0, 1e9)), &Body::bending_N_per_m,
            "Stiffness of the springs across each edge, which resist folding; 0 = none."),
      field("lattice", lattice_spec(), &Body::lattice,
            "Reduced model: voxels along the organ's longest side; their corners carry the motion and "
            "the mesh follows. Coarse: narrow regions lose much of their motion (docs/accuracy.md); "
            "a lower mesh.detail is the accurate way to save time. 0 = full model, every vertex a particle. "
            "`auto`: 12 for a mesh file that is open, in several pieces or over 50,000 vertices (an atlas "
            "organ of many parts: one volumetric body keeps them together), else 0; `validate` says which "
            "and why.")
          .shown_default("auto"),
      field("volume_drive", drive_spec(), &Body::volume_drive,
            "Drives the rest volume instead of rest lengths: V0(t) = V0 (1 + amplitude phi(t - delay)), "
            "`amplitude` the fraction of volume added (lungs inflating). Needs `volume_stiffness` > 0 "
            "and a closed surface."),
      field("fibre_tension", number(closed(0, 1)), &Body::fibre_tension,
            "Muscle with fibres (the anatomical heart): the fibres' tension beside their active strain. "
            "A driven fibre's rest length shortens by a further 1 - fibre_tension x contraction that the "
            "other directions do not take up, so the layer that pulls harder wins: the ventricle twists "
            "(docs/anatomy.md). 0 = the strain alone. Has no effect on a body without fibres."),
  });
}

}  // namespace systole::scene::schema

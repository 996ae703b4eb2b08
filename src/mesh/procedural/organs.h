#pragma once
// The generators behind generate_organ(): one file per organ in mesh/procedural/.

#include "mesh/mesh.h"

namespace systole::mesh::procedural {

/// About how many triangles a generator aims for at `detail` (1..6): 1200 * 2^(detail-1).
int target_triangles(int detail);

/// A heart, about 12 cm base to apex: +Y towards the head, +Z anterior (the viewer),
/// apex down, forward and to +X (the patient's left). Parts: left_ventricle,
/// right_ventricle, left_atrium, right_atrium, apex, aorta, pulmonary_trunk,
/// superior_vena_cava, inferior_vena_cava.
OrganMesh heart(int detail);

/// The anatomical heart (procedural/anatomical_heart.cpp): the same place and size as
/// heart(), hollow, with four chambers in muscular walls, the septa, atrial appendages, four
/// valves, hollow great vessels and coronary arteries, and its anatomy (mesh/anatomy.h): a
/// volumetric myocardium with fibre directions, the cavities, valves and landmarks. Parts:
/// heart()'s, and pulmonary_veins, the four <chamber>_cavity linings, interventricular_septum,
/// interatrial_septum, left_atrial_appendage, right_atrial_appendage, mitral_valve,
/// tricuspid_valve, aortic_valve, pulmonary_valve, coronary_arteries.
OrganMesh anatomical_heart(int detail);

/// Both lungs, about 25 cm apex to base and 28 cm across, as two closed surfaces plus the
/// airway (trachea and main bronchi) as a third. The left lung is the smaller, hollowed by
/// the heart, with the cardiac notch. Parts: right_upper_lobe, right_middle_lobe,
/// right_lower_lobe, left_upper_lobe, left_lower_lobe, trachea (the airway stub: trachea and main bronchi).
OrganMesh lungs(int detail);

/// A left kidney, about 11 cm long, hilum facing medially (-X). Parts: upper_pole,
/// interpolar, lower_pole (the cortex along the long axis), hilum (vessel and ureter stubs).
OrganMesh kidney(int detail);

/// A liver, about 22 cm wide. Parts: right_lobe, left_lobe (divided at the falciform
/// ligament), gallbladder, inferior_vena_cava (a stub at the back of the dome).
OrganMesh liver(int detail);

/// The diaphragm (procedural/thorax.cpp): a muscular dome 30 cm wide and 23 cm deep rising
/// 5 cm above its rim, its crest 4 cm in front of the centre, the right side higher, 8 mm
/// thick, a closed solid. Parts:
/// central_tendon, right_dome, left_dome, muscular_rim, costal_margin (the outer twentieth,
/// where it is held by the ribs).
OrganMesh diaphragm(int detail);

/// The chest wall (procedural/thorax.cpp): a band of ribs 33 cm tall around the lungs,
/// 12 mm thick, open at the top and bottom (a closed solid: a thick tube), narrowing towards
/// the apex. Parts: ribs, intercostal (bands between them), sternum (front), spine (back).
OrganMesh chest_wall(int detail);

}  // namespace systole::mesh::procedural

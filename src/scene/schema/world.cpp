// The world tables: solver, interactions, floor, camera, default lights.

#include "scene/schema/parts.h"

#include <Eigen/Geometry>
#include <cmath>

namespace systole::scene::schema {

ValueSpec<Solver> solver_spec() {
  // dt is a time or the word "auto", and sets two members: a custom field.
  const Range dt_range = open_closed(0, 0.1);
  Field<Solver> dt{KeySpec{"dt",
                           "time or `auto`",
                           "1/60 s",
                           dt_range.text("s") + ", or `auto`",
                           "Step size; `auto` lets the solver choose from the drive and stiffness.",
                           {}},
                   false, [dt_range](const Node& node, Solver& s, const std::string& path, const Context&) {
                     if (node.kind == Node::Kind::kScalar && node.scalar == "auto") {
                       s.auto_dt = true;
                       return;
                     }
                     const double v = parse_quantity(node, Dimension::kTime, path);
                     check_range(node, v, Dimension::kTime, dt_range, path);
                     s.auto_dt = false;
                     s.dt_s = v;
                   }};
  return map<Solver>(
      {
          field("method",
                choice<SolverMethod>({{"xpbd", SolverMethod::kXpbd},
                                      {"explicit", SolverMethod::kExplicit},
                                      {"implicit", SolverMethod::kImplicit},
                                      {"projective", SolverMethod::kProjective}}),
                &Solver::method,
                "Projective Dynamics with BDF2 (accurate at frame-sized steps), XPBD with substeps, explicit "
                "mass-spring (symplectic Euler), or linearized implicit Euler (docs/accuracy.md compares them)."),
          dt,
          field("substeps", whole<int>(1, 200), &Solver::substeps, "Substeps per step (XPBD, explicit, projective)."),
          field("iterations", whole<int>(1, 50), &Solver::iterations,
                "Projective: local/global iterations per substep."),
          field("threads", whole<int>(1, 64), &Solver::threads,
                "Threads for the spring loops; frames are bit-identical at any count."),
      },
      [](const Node& node, Solver& s, const std::string&, const Context&) { s.origin = node.origin; });
}

ValueSpec<Interaction> interaction_spec() {
  auto common = [](std::vector<Field<Interaction>> extra) {
    std::vector<Field<Interaction>> fields = {
        field("organ", name_text(), &Interaction::organ, "Name of the organ touched.").required(),
        field("at", vec3(Dimension::kLength), &Interaction::at_m,
              "Centre of the touched patch (world space, rest shape).")
            .required(),
        field("radius", quantity(Dimension::kLength, open_closed(0, 1000)), &Interaction::radius_m,
              "Vertices within this distance of `at` are touched."),
    };
    fields.insert(fields.end(), extra.begin(), extra.end());
    return fields;
  };
  auto poke = map<Interaction>(common({
      field("force", vec3(Dimension::kForce), &Interaction::force_N, "Total force, shared by the patch's vertices.")
          .required(),
      field("start", quantity(Dimension::kTime, closed(0, 3600)), &Interaction::start_s, "When the push starts."),
      field("duration", quantity(Dimension::kTime, open_closed(0, 3600)), &Interaction::duration_s,
            "How long the push lasts."),
      field("drive", drive_spec(), &Interaction::drive,
            "When given, the force is scaled by the drive's phi(t) all clip long instead (a periodic push: the "
            "diaphragm on the liver); start and duration are then unused."),
  }));
  auto grab = map<Interaction>(common({
      field("path", path_keys("Where the handle is."), &Interaction::path,
            "Handle positions at increasing times; the patch follows from the first key and is let go after the last.")
          .required(),
      field("stiffness", quantity(Dimension::kStiffness, open_closed(0, 1e9)), &Interaction::stiffness_N_per_m,
            "Stiffness holding each vertex to the handle."),
  }));
  return map<Interaction>(
      {
          field<Interaction, Interaction>(
              "poke", poke,
              [](Interaction& i) -> Interaction& {
                i.kind = InteractionKind::kPoke;
                return i;
              },
              "Push the vertices near `at` with `force` from `start` for `duration`."),
          field<Interaction, Interaction>(
              "grab", grab,
              [](Interaction& i) -> Interaction& {
                i.kind = InteractionKind::kGrab;
                return i;
              },
              "Drag the vertices near `at` along `path`, then let go."),
      },
      [](const Node& node, Interaction& i, const std::string& path, const Context&) {
        if (node.entries.size() != 1)
          fail(node.origin, path,
               "an interaction has exactly one of poke, grab; got " + std::to_string(node.entries.size()) + " keys");
        i.origin = node.origin;
      });
}

ValueSpec<Floor> floor_spec() {
  return map<Floor>(
      {
          field("point", vec3(Dimension::kLength), &Floor::point_m, "A point on the plane."),
          field("normal", direction(), &Floor::normal, "Points to the free side (normalised on reading)."),
      },
      [](const Node&, Floor& f, const std::string&, const Context&) {
        f.enabled = true;
        f.normal.normalize();
      });
}

ValueSpec<Contact> contact_spec() {
  const Range thickness = open_closed(0, 0.05), friction = closed(0, 2);
  auto organs = list(name_text(), 2, 2, "list of two organ names");
  auto pair = map<ContactPair>(
      {
          field("organs", organs, &ContactPair::organs,
              "The two organs that touch.")
              .required(),
          field<ContactPair, double>(
              "thickness", quantity(Dimension::kLength, thickness),
              [](ContactPair& p) -> double& {
                p.has_thickness = true;
                return p.thickness_m;
              },
              "This pair's gap; else `contact.thickness`.")
              .shown_default("contact.thickness"),
          field<ContactPair, double>(
              "friction", number(friction),
              [](ContactPair& p) -> double& {
                p.has_friction = true;
                return p.friction;
              },
              "This pair's friction; else `contact.friction`.")
              .shown_default("contact.friction"),
      },
      [](const Node& node, ContactPair& p, const std::string& path, const Context&) {
        p.origin = node.origin;
        if (p.organs[0] == p.organs[1]) fail(origin_of(node, "organs"), join(path, "organs"), "an organ does not touch itself here; name two organs");
      });
  return map<Contact>(
      {
          field("thickness", quantity(Dimension::kLength, thickness), &Contact::thickness_m,
                "Gap kept between two organs' surfaces (every pair unless it sets its own)."),
          field("friction", number(friction), &Contact::friction, "Coulomb friction coefficient between two organs."),
          field("iterations", whole<int>(1, 50), &Contact::iterations, "Projection passes over the contacts per contact step."),
          field("substeps", whole<int>(1, 50), &Contact::substeps,
                "Contact steps per solver step (each organ steps dt / substeps between them)."),
          field("pairs", list(pair, 0, 256, "list of pairs"), &Contact::pairs,
                "The pairs that touch; empty: every two organs (two colliders never)."),
      },
      [](const Node& node, Contact& c, const std::string&, const Context&) {
        c.enabled = true;
        c.origin = node.origin;
      });
}

ValueSpec<Camera> camera_spec() {
  auto orbit = map<Orbit>(
      {
          field("speed", quantity(Dimension::kAngularSpeed, closed(-3600, 3600)), &Orbit::speed_rad_per_s,
                "Turning speed; negative turns the other way."),
          field("axis", direction(), &Orbit::axis,
                "Axis through the target the eye turns about (normalised on reading)."),
      },
      [](const Node&, Orbit& o, const std::string&, const Context&) {
        o.enabled = true;
        o.axis.normalize();
      });
  auto key = map<CameraKey>({
      field("time", quantity(Dimension::kTime, closed(0, 3600)), &CameraKey::time_s, "When the camera is here.")
          .required(),
      field("position", vec3(Dimension::kLength), &CameraKey::position_m, "Eye position.").required(),
      field("target", vec3(Dimension::kLength), &CameraKey::target_m, "Point looked at.").required(),
  });
  auto path_spec = list(key, 1, 1024, "list of camera keys")
                       .also(
                           [](const std::vector<CameraKey>& keys) {
                             for (std::size_t i = 1; i < keys.size(); ++i)
                               if (keys[i].time_s <= keys[i - 1].time_s)
                                 return "times must increase (key " + std::to_string(i) + ")";
                             return std::string();
                           },
                           "1..1024 keys, times increasing");
  auto camera = map<Camera>(
      {
          field("position", vec3(Dimension::kLength), &Camera::position_m,
                "Eye position. Without one (and without a path) the camera frames the organs itself.")
              .shown_default("auto"),
          field("target", vec3(Dimension::kLength), &Camera::target_m, "Point looked at (with `position`).")
              .shown_default("auto"),
          field("fill", number(open_closed(0, 1)), &Camera::fill,
                "With no `position`: the share of the frame's smaller side the organs' bounding sphere fills."),
          field("up", direction(), &Camera::up, "Up direction (not parallel to the view)."),
          field("fov", quantity(Dimension::kAngle, open(1, 170)), &Camera::fov_rad, "Vertical field of view."),
          field("orbit", orbit, &Camera::orbit,
                "Turntable: the eye turns about `axis` through the target, starting at `position`.")
              .shown_default("none"),
          field("path", path_spec, &Camera::path,
                "Key-framed camera: a Catmull-Rom curve through the keys' positions and targets, held before the first "
                "and after the last; `position` and `target` are then unused."),
      },
      [](const Node& node, Camera& c, const std::string& path, const Context&) {
        if (c.orbit.enabled && !c.path.empty())
          fail(origin_of(node, "orbit"), join(path, "orbit"), "a camera has an orbit or a path, not both");
        c.automatic = node.find("position") == nullptr && c.path.empty();
        if (c.automatic) {
          if (node.find("target") != nullptr)
            fail(origin_of(node, "target"), join(path, "target"),
                 "goes with " + join(path, "position") + "; give both, or neither and the camera frames the organs");
          if (std::abs(c.up.normalized().z()) > 1 - 1e-6)
            fail(origin_of(node, "up"), join(path, "up"),
                 "must not be parallel to the view direction of a camera that frames the organs (along -z)");
          return;
        }
        if (node.find("fill") != nullptr)
          fail(origin_of(node, "fill"), join(path, "fill"), "applies only to a camera that frames the organs (no position)");
        const auto check_view = [&](const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const std::string& at,
                                    const std::string& eye_key, const std::string& target_key) {
          const Eigen::Vector3d view = target - eye;
          if (view.norm() < 1e-9) fail(origin_of(node, at), join(path, target_key), "must differ from " + join(path, eye_key));
          if (view.normalized().cross(c.up.normalized()).norm() < 1e-6)
            fail(origin_of(node, "up"), join(path, "up"),
                 "must not be parallel to the view direction, from " + join(path, eye_key) + " to " +
                     join(path, target_key));
        };
        if (c.path.empty()) {
          check_view(c.position_m, c.target_m, "target", "position", "target");
        } else {
          for (std::size_t i = 0; i < c.path.size(); ++i) {
            const std::string key = "path[" + std::to_string(i) + "]";
            check_view(c.path[i].position_m, c.path[i].target_m, "path", key + ".position", key + ".target");
          }
          c.position_m = c.path.front().position_m;
          c.target_m = c.path.front().target_m;
        }
      });
  // `camera: auto` says what no camera says, explicitly.
  ValueSpec<Camera> spec = camera;
  spec.range = "`auto`, or a map";
  spec.read = [read_map = camera.read](const Node& node, Camera& c, const std::string& path, const Context& ctx) {
    if (node.kind == Node::Kind::kScalar && node.scalar == "auto") {
      c = Camera{};
      return;
    }
    read_map(node, c, path, ctx);
  };
  return spec;
}

/// A warm key light from the upper left and a cool, dimmer fill from the right, so the
/// organ reads as a solid even when a scene names no lights.
std::vector<Light> default_lights() {
  Light key;
  key.direction = Eigen::Vector3d(-0.4, -0.6, -1.0);
  key.color = Color(1.0, 0.96, 0.9);
  key.intensity = 1.0;
  Light fill;
  fill.direction = Eigen::Vector3d(0.7, 0.2, -0.7);
  fill.color = Color(0.8, 0.87, 1.0);
  fill.intensity = 0.35;
  return {key, fill};
}

}  // namespace systole::scene::schema

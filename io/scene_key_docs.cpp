#include "scene_keys.hpp"

namespace tide::io {

std::vector<SectionDoc> section_docs() {
  return {
      section_doc("top level", top_level_keys()),
      section_doc("kernel", kernel_keys()),
      section_doc("materials[i]", material_keys()),
      section_doc("fluid[i]", fluid_block_keys()),
      section_doc("fluid[i].velocity.taylor_green", taylor_green_keys()),
      section_doc("fluid[i].velocity.rotation", rotation_keys()),
      section_doc("box", box_keys()),
      section_doc("ball", ball_keys()),
      section_doc("plane", plane_keys()),
      section_doc("mesh", mesh_keys()),
      section_doc("mesh.rotation", mesh_rotation_keys()),
      section_doc("walls", wall_keys()),
      section_doc("walls.container", container_keys()),
      section_doc("walls.obstacles[i]", obstacle_keys()),
      section_doc("walls.obstacles[i].motion.rotation", rotation_motion_keys()),
      section_doc("walls.obstacles[i].motion.oscillation", oscillation_keys()),
      section_doc("walls.obstacles[i].motion.flap", flap_keys()),
      section_doc("walls.obstacles[i].motion.table", motion_table_keys()),
      section_doc("walls.obstacles[i].motion.steered", steered_keys()),
      section_doc("walls.obstacles[i].body", body_keys()),
      section_doc("walls.obstacles[i].body.constraints", body_constraint_keys()),
      section_doc("domain", domain_keys()),
      section_doc("domain.inflow", inflow_keys()),
      section_doc("solver", solver_keys()),
      section_doc("solver.surface_tension", surface_tension_keys()),
      section_doc("solver.body_contact", body_contact_keys()),
      section_doc("time", time_keys()),
      section_doc("output", output_keys()),
      section_doc("output.recovery", recovery_keys()),
      section_doc("probes[i]", probe_keys()),
      section_doc("crowd", crowd_keys()),
      section_doc("crowd.agents[i]", crowd_agent_keys()),
      section_doc("crowd.exits[i]", crowd_exit_keys()),
      section_doc("crowd.desired_speed", crowd_speed_keys()),
  };
}

}  // namespace tide::io

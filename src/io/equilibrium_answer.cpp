// equilibrium_answer.cpp: an equilibrium task answered, free or resting on its scene.
#include "rodshape/io/equilibrium_answer.hpp"

#include "rodshape/error.hpp"
#include "rodshape/io/field_names.hpp"
#include "rodshape/io/result_json.hpp"

namespace rodshape {

const ShootingResult& EquilibriumAnswer::solution() const {
  return contact ? contact->shooting : analysis->solution;
}

std::string EquilibriumAnswer::brief() const {
  return contact ? contact->shooting.brief() + "; " + contact->brief() : analysis->brief();
}

namespace {

/// An equilibrium's scene is what the rod rests on (as the reader checks a file's; a task changed
/// in code is checked here): every obstacle touchable, and the rod's section known.
void check_resting_scene(const EquilibriumTask& task) {
  for (std::size_t j = 0; j < task.scene.obstacles.size(); ++j)
    if (!task.scene.obstacles[j].touchable())
      throw InputError(task.source + ": scene.obstacles[" + std::to_string(j) +
                       "].contact: an equilibrium rests on its obstacles: give contact: touch "
                       "(avoid, the default, is for plans, which keep a clearance)");
  if (!task.scene.empty() && !task.rod.properties.section)
    throw InputError(task.source +
                     ": scene needs rod.section: the rod's surface is what rests on an obstacle");
}

}  // namespace

EquilibriumAnswer answer_equilibrium_task(const EquilibriumTask& task) {
  check_resting_scene(task);
  EquilibriumAnswer answer;
  try {
    if (task.scene.empty())
      answer.analysis = analyse_equilibrium(task.rod, task.tip, task.initial_wrench, task.options);
    else
      answer.contact = solve_contact_equilibrium(task.rod, task.tip, task.scene,
                                                 task.initial_wrench, task.options);
  } catch (const InputError& error) {  // a held pose beyond the model's validity or in a solid
    throw InputError(task.source + ": " + in_task_names(error));
  }
  return answer;
}

std::string equilibrium_answer_json(const EquilibriumAnswer& answer, const EquilibriumTask& task) {
  return answer.contact ? contact_equilibrium_result_json(*answer.contact, task.rod, task.scene)
                        : equilibrium_result_json(*answer.analysis);
}

}  // namespace rodshape

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

EquilibriumAnswer answer_equilibrium_task(const EquilibriumTask& task) {
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

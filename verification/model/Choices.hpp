#pragma once
// The names vorodg knows — problems, mesh families, element families, orderings,
// solvers, plane models and study kinds — each with a one-line doc. The command line, the scene
// reader, their messages, `--help` and docs/scenes.md all take the names from here.
#include <string>
#include <vector>

#include "core/element/ElementFamily.hpp"
#include "core/material/IsotropicElasticity.hpp"
#include "core/solve/LinearSolverChoice.hpp"
#include "interfaces/InterfacePenalty.hpp"

namespace vorodg {

struct NamedChoice {
  std::string name;
  std::string doc;
};
using Choices = std::vector<NamedChoice>;

const Choices& problem_choices();
const Choices& generated_family_choices();  // the families a scene or `--family` can generate
const Choices& ordering_choices();
const Choices& solver_choices();
const Choices& element_choices();  // the element families
const Choices& plane_choices();
const Choices& penalty_choices();   // how the DG penalty is scaled
const Choices& traction_choices();  // which stress of a cell the DG interface terms take
const Choices& study_choices();
const Choices& sweep_axis_choices();  // what an extremes sweep varies
const Choices& baseline_choices();    // what an extremes sweep compares errors with

bool is_choice(const Choices& choices, const std::string& name);
/// "a, b, c or d": the names, for messages.
std::string choice_list(const Choices& choices);
/// "a | b | c": the names, for `--help`.
std::string choice_alternatives(const Choices& choices);

FillOrdering parse_ordering(const std::string& name);
std::string ordering_name(FillOrdering ordering);
LinearSolverKind parse_solver(const std::string& name);
std::string solver_name(LinearSolverKind kind);
ElementFamily parse_element(const std::string& name);
std::string element_name(ElementFamily family);
PlaneModel parse_plane(const std::string& name);
std::string plane_name(PlaneModel plane);
PenaltyScaling parse_penalty(const std::string& name);
std::string penalty_name(PenaltyScaling scaling);
TractionKind parse_traction(const std::string& name);
std::string traction_name(TractionKind kind);

}  // namespace vorodg

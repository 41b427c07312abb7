#pragma once
// The names vorodg knows — problems, mesh families, element families, orderings,
// solvers, plane models and study kinds — each with a one-line doc. The command line, the scene
// reader, their messages, `--help` and docs/scenes.md all take the names from here.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/element/ElementFamily.hpp"
#include "core/material/IsotropicElasticity.hpp"
#include "core/solve/LinearSolverChoice.hpp"

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
const Choices& sweep_axis_choices();  // what an extremes sweep varies
const Choices& baseline_choices();    // what an extremes sweep compares errors with

/// A table of choices from text, one per line: the name, at least two spaces, its doc.
Choices choice_table(std::string_view text);

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

/// The enum value of a name: `values` lists the enum values in the order of `choices`; throws
/// std::invalid_argument naming the choices otherwise.
template <class Enum, std::size_t N>
Enum parse_enum(const Choices& choices, const Enum (&values)[N], const std::string& name) {
  for (std::size_t i = 0; i < N; ++i)
    if (choices.at(i).name == name) return values[i];
  throw std::invalid_argument("'" + name + "': expected " + choice_list(choices));
}

/// The name of an enum value ("?" for one not listed).
template <class Enum, std::size_t N>
std::string enum_name(const Choices& choices, const Enum (&values)[N], Enum value) {
  for (std::size_t i = 0; i < N; ++i)
    if (values[i] == value) return choices.at(i).name;
  return "?";
}

}  // namespace vorodg

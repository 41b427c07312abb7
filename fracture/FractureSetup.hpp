#pragma once
// What a cohesive-fracture run needs to know about its scene, in mesh terms (the problem layer
// builds it from the geometry): where cracks may form, which faces are a notch, which DOFs the
// machine moves and where the crack mouth opening is measured.
#include <string>
#include <vector>

namespace vorodg {

/// Where new crack faces may appear (the report's section 8 cases, in increasing generality).
enum class CrackingMode {
  pre_inserted,  // intrinsic cohesive faces on the crack line from the start
  restricted,    // extrinsic: intact until the criterion holds, only on the crack line
  contiguous,    // anywhere, but only at a face touching the notch or an existing crack
  arbitrary,     // anywhere
};

/// Parses pre-inserted, restricted, contiguous, arbitrary; throws InputError otherwise.
CrackingMode parse_cracking_mode(const std::string& name);
std::string cracking_mode_name(CrackingMode mode);
/// Whether any interior edge may crack (all but pre-inserted and restricted keep only the line).
inline bool cracks_anywhere(CrackingMode m) {
  return m == CrackingMode::contiguous || m == CrackingMode::arbitrary;
}

/// A vertex's displacement component prescribed as lambda * reference (every node at the vertex).
struct VertexConstraint {
  int vertex;
  int component;  // 0: x, 1: y
  double reference;
};

/// The opening across the crack line, as a weighted sum over vertices on it: at each, u_x of its
/// right-hand node minus u_x of its left-hand one (the nodes of the left-most and right-most
/// cells at the vertex). One vertex with weight 1 is a crack mouth opening gauge; all the
/// line's vertices with length weights give the mean opening of the line.
struct MouthGauge {
  std::vector<int> vertices;
  std::vector<double> weights;
};

struct FractureSetup {
  CrackingMode mode = CrackingMode::restricted;
  std::vector<char> line;   // per mesh edge: on the crack line (and not on the notch)
  std::vector<char> notch;  // per mesh edge: traction-free from the start
  std::vector<VertexConstraint> constraints;
  int load_vertex = -1;  // where the stroke is measured: the first constraint with reference != 0
  MouthGauge mouth;
  double thickness = 1.0;  // out of plane: forces and energies per unit thickness times this
  /// Split every interior edge (the full DG space) whatever the mode, to measure what splitting
  /// only the crack-capable edges saves. Not the same answer: intact edges are then coupled
  /// weakly (SIPG) instead of sharing nodes, which makes the body slightly softer.
  bool split_all = false;
};

}  // namespace vorodg

#include "fracture/FractureSetup.hpp"

#include "core/util/Errors.hpp"

namespace vorodg {

CrackingMode parse_cracking_mode(const std::string& name) {
  for (CrackingMode m : {CrackingMode::pre_inserted, CrackingMode::restricted,
                         CrackingMode::contiguous, CrackingMode::arbitrary})
    if (cracking_mode_name(m) == name) return m;
  throw InputError("cracking mode '" + name +
                   "': expected pre-inserted, restricted, contiguous or arbitrary");
}

std::string cracking_mode_name(CrackingMode mode) {
  switch (mode) {
    case CrackingMode::pre_inserted: return "pre-inserted";
    case CrackingMode::restricted: return "restricted";
    case CrackingMode::contiguous: return "contiguous";
    case CrackingMode::arbitrary: break;
  }
  return "arbitrary";
}

}  // namespace vorodg

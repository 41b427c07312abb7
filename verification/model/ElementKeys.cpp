#include "verification/model/ElementKeys.hpp"

#include "core/element/ElementTable.hpp"
#include "core/util/Format.hpp"
#include "verification/model/Choices.hpp"

namespace vorodg {

std::vector<SceneKey> element_keys() {
  return {key("element", "string", element_name(ElementOptions{}.family),
              choice_list(element_choices()),
              "the element: its shape functions (docs/element.md, \"Which element for what\")"),
          bounded("vem_stabilization", "number", exact_text(ElementOptions{}.vem_stabilization),
                  "0 < tau <= 1e6",
                  "vem: the stabilization's scale tau, times trace(K_consistency) / (2n)", 0.0,
                  true, 1e6)};
}

}  // namespace vorodg

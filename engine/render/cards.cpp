#include "cards.hpp"

namespace arbor::render {

std::vector<std::uint32_t> cardIndices(std::uint32_t cards) {
  std::vector<std::uint32_t> indices;
  indices.reserve(6u * cards);
  for (std::uint32_t card = 0; card < cards; ++card) {
    for (const std::uint32_t slot : {0u, 1u, 3u, 0u, 3u, 2u}) indices.push_back(4u * card + slot);
  }
  return indices;
}

}  // namespace arbor::render

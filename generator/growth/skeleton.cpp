#include "skeleton.hpp"

namespace arbor {

const char* nodeKindName(NodeKind kind) {
  switch (kind) {
    case NodeKind::Root: return "root";
    case NodeKind::Base: return "base";
    case NodeKind::Joint: return "joint";
    case NodeKind::Attachment: return "attachment";
    case NodeKind::Split: return "split";
    case NodeKind::Before: return "before";
    case NodeKind::After: return "after";
    case NodeKind::Tip: return "tip";
  }
  return "joint";
}

}  // namespace arbor

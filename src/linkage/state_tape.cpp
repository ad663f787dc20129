#include "reconfig/linkage/state_tape.h"

namespace reconfig::linkage {

void StateTape::pull_back(const Eigen::Matrix2Xd& G, Eigen::Matrix2Xd& out) const {
  adjoint_ = G;  // ∂f/∂x_k, growing as later joints pass their sensitivity back
  for (auto step = steps.rbegin(); step != steps.rend(); ++step) {
    if (step->block >= 0) {
      const Block& block = blocks[step->block];
      Eigen::VectorXd gy(2 * static_cast<Eigen::Index>(block.outputs.size()));
      for (std::size_t b = 0; b < block.outputs.size(); ++b)
        gy.segment<2>(2 * static_cast<Eigen::Index>(b)) = adjoint_.col(block.outputs[b]);
      if (gy.isZero()) continue;
      const Eigen::VectorXd g_in = block.S_in.transpose() * gy, g_param = block.S_param.transpose() * gy;
      for (std::size_t z = 0; z < block.inputs.size(); ++z)
        adjoint_.col(block.inputs[z]) += g_in.segment<2>(2 * static_cast<Eigen::Index>(z));
      for (std::size_t p = 0; p < block.params.size(); ++p)
        out.col(block.params[p]) += g_param.segment<2>(2 * static_cast<Eigen::Index>(p));
      continue;
    }
    const Eigen::Vector2d g = adjoint_.col(step->k);
    if (g.x() == 0 && g.y() == 0) continue;
    out.col(step->k) += step->Pk.transpose() * g;
    if (step->i >= 0) {
      adjoint_.col(step->i) += step->Mi.transpose() * g;
      out.col(step->i) += step->Pi.transpose() * g;
    }
    if (step->j >= 0) {
      adjoint_.col(step->j) += step->Mj.transpose() * g;
      out.col(step->j) += step->Pj.transpose() * g;
    }
  }
}

}  // namespace reconfig::linkage

// An optional FST waveform of a Verilated model, shared by the SystemC bench and the plain C++
// harness: open() attaches the model, dump() records a time step, close() finishes the file.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "verilated_fst_c.h"

namespace watkins::tb {

class FstTrace {
 public:
  template <class Model>
  bool open(Model& model, const std::string& path) {
    fst_ = std::make_unique<VerilatedFstC>();
    model.trace(fst_.get(), 99);
    fst_->open(path.c_str());
    if (!fst_->isOpen()) fst_.reset();
    return fst_ != nullptr;
  }
  void dump(std::uint64_t t) {
    if (fst_) fst_->dump(t);
  }
  void close() {
    if (fst_) fst_->close();
    fst_.reset();
  }

 private:
  std::unique_ptr<VerilatedFstC> fst_;
};

}  // namespace watkins::tb

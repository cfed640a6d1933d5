#pragma once

// The stamps of the clouds a node receives: a cloud whose stamp is not
// after the last one used (a repeated or an older stamp) is refused, and an
// interval longer than kGapFactor times the last regular one is noted as a
// gap (messages dropped on the way, or by the subscription's queue when the
// node falls behind).

#include <string>

namespace mlndt {
namespace ros_core {

class StampCheck {
 public:
  static constexpr double kGapFactor = 1.5;

  // False with *refusal when `stamp_s` is not after the last stamp used.
  // Else true; *gap_note gets a note when the interval is a gap (else it is
  // cleared). The stamp counts as used only after Use(stamp_s).
  bool Check(double stamp_s, std::string* refusal, std::string* gap_note) const;
  // Records a stamp the node used.
  void Use(double stamp_s);
  // Forgets every stamp (a restart).
  void Reset();

 private:
  bool has_last_ = false;
  double last_s_ = 0.0;
  double regular_interval_s_ = 0.0;  // 0 until two stamps were used.
};

}  // namespace ros_core
}  // namespace mlndt

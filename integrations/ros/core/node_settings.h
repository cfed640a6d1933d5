#pragma once

// The nodes' own settings (not the library's options): how often the
// odometry publishes its local map, the subscription's queue, whether tf is
// published, how long the localiser waits for odom -> sensor. Described by
// option tables like the library's options, so they are read, checked and
// documented the same way (option_parameters.h), named as their fields.

#include <string>

#include "mlndt/common/option_table.h"

namespace mlndt {
namespace ros_core {

struct OdometryNodeSettings {
  // Scan-stamp time between two local-map clouds [s]; 0 = after every
  // scan. In [0, 3600].
  double local_map_period_s = 1.0;
  // Clouds waiting in the subscription; older ones are dropped when the
  // node falls behind (a gap in the stamps then says so). >= 1.
  int queue_size = 10;
  // Publish odom -> sensor on tf.
  bool publish_tf = true;
};

struct LocalizerNodeSettings {
  // How long a scan waits for odom -> sensor at its stamp on tf (from an
  // odometry node) [s]. In (0, 60].
  double tf_timeout_s = 1.0;
  int queue_size = 10;  // As OdometryNodeSettings::queue_size. >= 1.
  bool publish_tf = true;
};

const OptionTable& OdometryNodeSettingsTable();
const OptionTable& LocalizerNodeSettingsTable();

}  // namespace ros_core
}  // namespace mlndt

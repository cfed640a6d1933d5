#include "integrations/ros/core/node_settings.h"

namespace mlndt {
namespace ros_core {

const OptionTable& OdometryNodeSettingsTable() {
  using S = OdometryNodeSettings;
  static const OptionTable table =
      OptionTableBuilder<S>("OdometryNodeSettings")
          .Double("local_map_period_s",
                  &S::local_map_period_s,
                  "s",
                  Closed(0.0, 3600.0),
                  "Scan-stamp time between two local-map clouds; 0 = after "
                  "every scan.")
          .Int("queue_size",
               &S::queue_size,
               AtLeast(1),
               "Clouds waiting in the subscription (older ones are dropped "
               "when the node falls behind).")
          .Bool("publish_tf", &S::publish_tf, "Publish odom -> sensor on tf.")
          .Build();
  return table;
}

const OptionTable& LocalizerNodeSettingsTable() {
  using S = LocalizerNodeSettings;
  static const OptionTable table =
      OptionTableBuilder<S>("LocalizerNodeSettings")
          .Double("tf_timeout_s",
                  &S::tf_timeout_s,
                  "s",
                  LeftOpen(0.0, 60.0),
                  "How long a scan waits for odom -> sensor at its stamp on "
                  "tf (from an odometry node).")
          .Int("queue_size",
               &S::queue_size,
               AtLeast(1),
               "Clouds waiting in the subscription (older ones are dropped "
               "when the node falls behind).")
          .Bool("publish_tf", &S::publish_tf, "Publish map -> odom on tf.")
          .Build();
  return table;
}

}  // namespace ros_core
}  // namespace mlndt

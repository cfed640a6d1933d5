#include "tools/cli/option_flags_store.h"

#include <gflags/gflags.h>

#include <deque>

namespace mlndt {
namespace tools {
namespace {

// The flags' storage, which lives as long as the program.
class FlagStore {
 public:
  void Register(const std::string& name,
                const std::string& help,
                const char* file,
                OptionType type,
                const std::string& value) {
    const char* n = strings_.emplace_back(name).c_str();
    const char* h = strings_.emplace_back(help).c_str();
    switch (type) {
      case OptionType::BOOL:
        return Add(n, h, file, &bools_, value == "true");
      case OptionType::INT:
        return Add(
            n, h, file, &ints_, static_cast<gflags::int32>(std::stoi(value)));
      case OptionType::UINT64:
        return Add(n,
                   h,
                   file,
                   &uints_,
                   static_cast<gflags::uint64>(std::stoull(value)));
      case OptionType::DOUBLE:
        return Add(n, h, file, &doubles_, std::stod(value));
      default:
        return Add(n, h, file, &texts_, value);
    }
  }

 private:
  template <typename T>
  void Add(const char* name,
           const char* help,
           const char* file,
           std::deque<T>* store,
           T v) {
    store->push_back(v);
    T* current = &store->back();
    store->push_back(v);
    new gflags::FlagRegisterer(name, help, file, current, &store->back());
  }

  std::deque<std::string> strings_;
  std::deque<bool> bools_;
  std::deque<gflags::int32> ints_;
  std::deque<gflags::uint64> uints_;
  std::deque<double> doubles_;
  std::deque<std::string> texts_;
};

}  // namespace

void RegisterOptionFlag(const std::string& name,
                        const std::string& help,
                        const char* file,
                        OptionType type,
                        const std::string& default_text) {
  static FlagStore store;
  store.Register(name, help, file, type, default_text);
}

}  // namespace tools
}  // namespace mlndt

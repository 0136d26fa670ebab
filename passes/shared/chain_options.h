#pragma once
// A method's own options for one light's chain (its sizes, its variants), held by the frame's graph
// configuration without the configuration knowing the type: two are equal when they hold the same
// type and that type's operator== says so. A method's options struct compares with `= default`,
// so no field can be left out of the comparison that decides whether a graph is rebuilt.
#include <memory>
#include <typeinfo>

namespace ls {

class ChainOptions {
  public:
    ChainOptions() = default;
    template <typename T>
    explicit ChainOptions(T value) : held_(std::make_shared<Holder<T>>(std::move(value))) {}

    // The options as the method that made them; null when they are of another type (or none).
    template <typename T>
    const T* get() const {
        auto* h = dynamic_cast<const Holder<T>*>(held_.get());
        return h ? &h->value : nullptr;
    }
    bool operator==(const ChainOptions& o) const {
        if (!held_ || !o.held_) return !held_ && !o.held_;
        return held_->equals(*o.held_);
    }

  private:
    struct Base {
        virtual ~Base() = default;
        virtual bool equals(const Base& o) const = 0;
    };
    template <typename T>
    struct Holder final : Base {
        explicit Holder(T v) : value(std::move(v)) {}
        bool equals(const Base& o) const override {
            auto* h = dynamic_cast<const Holder<T>*>(&o);
            return h && h->value == value;
        }
        T value;
    };
    std::shared_ptr<const Base> held_;
};

}  // namespace ls

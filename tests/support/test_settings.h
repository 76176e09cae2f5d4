// Settings as a test states them: the name = value pairs in one brace list instead of a set()
// call each. Every value is checked against the settings table as any input is (an unknown name,
// a value out of range or a choice an enum lacks throws InputError naming the test).
#pragma once

#include "settings/settings.h"

#include <initializer_list>
#include <string_view>
#include <type_traits>

namespace ispm::test {

// One setting: a number, or an enum's choice by name.
class TestSetting {
  public:
    template <typename T>
    requires std::is_arithmetic_v<T> TestSetting(std::string_view name, T value)
        : mName(name), mNumber(static_cast<double>(value)) {}
    TestSetting(std::string_view name, std::string_view choice)
        : mName(name), mChoice(choice), mIsChoice(true) {}

    void applyTo(Settings& settings) const {
        if (mIsChoice) {
            settings.setEnum(mName, mChoice, "test");
        } else {
            settings.set(mName, mNumber, "test");
        }
    }

  private:
    std::string_view mName;
    double mNumber = 0.0;
    std::string_view mChoice;
    bool mIsChoice = false;
};

// `base` with `values` laid over it.
inline Settings withSettings(Settings base, std::initializer_list<TestSetting> values) {
    for (const TestSetting& value : values)
        value.applyTo(base);
    return base;
}

// The table's defaults with `values` laid over them.
inline Settings makeTestSettings(std::initializer_list<TestSetting> values) {
    return withSettings(Settings(), values);
}

} // namespace ispm::test

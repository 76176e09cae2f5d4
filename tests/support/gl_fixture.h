// GL test support: one headless context for the whole test executable, and a fixture that fails
// any test during which KHR_debug reported an error.
#pragma once

#include "gl/context.h"
#include "gl/debug.h"

#include <gtest/gtest.h>

#include <memory>

namespace ispm::test {

gl::Context& getTestContext();

class GlTest : public ::testing::Test {
  protected:
    void SetUp() override;
    void TearDown() override;
};

} // namespace ispm::test

#include <gtest/gtest.h>
TEST(CliRotation, Placeholder) {
  SUCCEED();
}

// SPDX-License-Identifier: MIT
// The store tests' fixture: each test gets a fresh store on the backend it is instantiated for.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "store.h"
#include "store_test_backends.h"

namespace flange::testing {

class StoreTest : public ::testing::TestWithParam<StoreBackendUnderTest> {
 protected:
  void SetUp() override {
    url_ = fresh_store_url(GetParam(),
                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  std::unique_ptr<host::Store> open() { return host::open_store(url_); }
  const std::string& url() const { return url_; }

 private:
  std::string url_;
};

inline std::string backend_param_name(const ::testing::TestParamInfo<StoreBackendUnderTest>& info) {
  return backend_test_name(info.param);
}

}  // namespace flange::testing

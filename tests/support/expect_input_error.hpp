#pragma once
// Runs f, which must throw a mesochain::InputError whose message holds every fragment (file,
// key, found, expected ...): the check every error-message test makes.
#include <functional>
#include <initializer_list>
#include <string>

#include <gtest/gtest.h>

#include "common/errors.hpp"

namespace mesochain::testing {

inline void expectInputError(const std::function<void()>& f, std::initializer_list<const char*> fragments) {
  try {
    f();
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    for (const char* s : fragments) EXPECT_NE(m.find(s), std::string::npos) << m << " lacks " << s;
  }
}

}  // namespace mesochain::testing

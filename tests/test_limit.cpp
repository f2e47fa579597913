// Limit stencils: closed forms, unit sums, orientation, the faces-only level and composition.
#include <gtest/gtest.h>

int placeholderLimit = 0;

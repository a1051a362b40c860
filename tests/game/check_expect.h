// EXPECT for the standalone check programs the game's scripted tests run (play_through_check,
// walk_check): a failed condition prints "FAIL: ..." and counts in `failures`, and main returns
// non-zero when any failed.
#pragma once

#include <cstdio>

inline int failures = 0;

#define EXPECT(cond, ...)                      \
    do {                                       \
        if (!(cond)) {                         \
            std::printf("FAIL: " __VA_ARGS__); \
            std::printf("\n");                 \
            ++failures;                        \
        }                                      \
    } while (0)

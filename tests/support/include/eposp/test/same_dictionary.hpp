#pragma once

// Compares a dictionary read back from an EDS with the one it was exported from: what an EDS
// carries of each object (CiA 306); persistence and hooks are not part of it.
#include "eposp/canopen/object_dictionary.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace eposp::test {

inline void expect_same_entry(const canopen::SubObject& imported, const canopen::SubObject& built) {
    EXPECT_EQ(imported.name, built.name);
    EXPECT_EQ(imported.type, built.type);
    EXPECT_EQ(imported.access, built.access);
    EXPECT_EQ(imported.pdo_mappable, built.pdo_mappable);
    EXPECT_EQ(imported.default_value, built.default_value);
    EXPECT_EQ(imported.low_limit, built.low_limit);
    EXPECT_EQ(imported.high_limit, built.high_limit);
}

inline void expect_same_objects(const canopen::ObjectDictionary& imported,
                                const canopen::ObjectDictionary& built) {
    const auto& objects = imported.objects();
    ASSERT_EQ(objects.size(), built.objects().size());
    for (const auto& [index, object] : built.objects()) {
        const auto found = objects.find(index);
        ASSERT_NE(found, objects.end()) << fmt::format("0x{:04X}", index);
        EXPECT_EQ(found->second.name, object.name);
        EXPECT_EQ(found->second.code, object.code);
        ASSERT_EQ(found->second.subs.size(), object.subs.size()) << fmt::format("0x{:04X}", index);
        for (const auto& [sub_index, sub] : object.subs) {
            SCOPED_TRACE(fmt::format("0x{:04X} sub {}", index, sub_index));
            expect_same_entry(found->second.subs.at(sub_index), sub);
        }
    }
}

} // namespace eposp::test

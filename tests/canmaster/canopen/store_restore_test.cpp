#include "eposp/canopen/parameter_store.hpp"
#include "eposp/canopen/store_restore_objects.hpp"
#include "eposp/test/test_directory.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <string>

namespace eposp::canopen {
namespace {

namespace fs = std::filesystem;

Bytes read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_file(const fs::path& path, const Bytes& content) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(content.data()),
              static_cast<std::streamsize>(content.size()));
}

// A small device: some persistent parameters, one volatile value, 0x1010/0x1011 on a file in a
// directory of its own.
class StoreRestore : public testing::Test {
protected:
    void SetUp() override {
        build(od_);
        add_store_restore_objects(od_, store_, {.restore_permitted = [this] {
                                      return restore_refusal_;
                                  }});
    }

    static void build(ObjectDictionary& od) {
        od.add_variable(0x1017, "Producer heartbeat time", DataType::Unsigned16, Access::ReadWrite,
                        encode<std::uint16_t>(0))
            .persistent = true;
        od.add_variable(0x1008, "Device name", DataType::VisibleString, Access::ReadWrite,
                        encode_string("EPOS2"))
            .persistent = true;
        od.add_object(0x2080, "Limits", ObjectCode::Record);
        od.add_sub(0x2080, 1, "Max velocity", DataType::Integer32, Access::ReadWrite,
                   encode<std::int32_t>(-1))
            .persistent = true;
        od.add_sub(0x2080, 2, "Gain", DataType::Real32, Access::ReadWrite, encode(0.5F))
            .persistent = true;
        od.add_variable(0x6041, "Statusword", DataType::Unsigned16, Access::ReadWrite,
                        encode<std::uint16_t>(0x40));
    }

    AbortCode write_u32(std::uint16_t index, std::uint8_t sub_index, std::uint32_t value) {
        return od_.write(index, sub_index, encode(value));
    }

    void change_every_value() {
        od_.set_as<std::uint16_t>(0x1017, 0, 100);
        od_.set(0x1008, 0, encode_string("a longer device name"));
        od_.set_as<std::int32_t>(0x2080, 1, 25000);
        od_.set_as<float>(0x2080, 2, 1.25F);
        od_.set_as<std::uint16_t>(0x6041, 0, 0x237);
    }

    fs::path path() const { return directory_ / "parameters.bin"; }

    fs::path directory_ = test::test_directory();
    ObjectDictionary od_;
    ParameterStore store_{od_, directory_ / "parameters.bin"};
    AbortCode restore_refusal_ = AbortCode::None;
};

TEST_F(StoreRestore, SaveSignaturePersistsPersistentValuesThatPowerUpApplies) {
    change_every_value();
    ASSERT_EQ(write_u32(0x1010, 1, kSaveSignature), AbortCode::None);
    od_.set_as<std::uint16_t>(0x1017, 0, 5); // changed after the save: lost at power-up

    const StoredValuesReport report = store_.load_stored_values();

    EXPECT_EQ(report.status, StoredValuesStatus::Applied);
    EXPECT_FALSE(report.refused());
    EXPECT_EQ(od_.get_as<std::uint16_t>(0x1017, 0), 100);
    EXPECT_EQ(od_.get(0x1008, 0), encode_string("a longer device name"));
    EXPECT_EQ(od_.get_as<std::int32_t>(0x2080, 1), 25000);
    EXPECT_EQ(od_.get_as<float>(0x2080, 2), 1.25F);
    EXPECT_EQ(od_.get_as<std::uint16_t>(0x6041, 0), 0x40) << "not persistent: default";
}

TEST_F(StoreRestore, SaveLeavesNoTemporaryFileAndASecondSaveReplacesTheFirst) {
    ASSERT_EQ(write_u32(0x1010, 1, kSaveSignature), AbortCode::None);
    change_every_value();
    ASSERT_EQ(write_u32(0x1010, 1, kSaveSignature), AbortCode::None);
    EXPECT_FALSE(fs::exists(fs::path(path()) += ".tmp"));
    EXPECT_EQ(store_.load_stored_values().status, StoredValuesStatus::Applied);
    EXPECT_EQ(od_.get_as<std::uint16_t>(0x1017, 0), 100);
}

TEST_F(StoreRestore, AnInterruptedSaveLeavesTheLastCompleteStore) {
    change_every_value();
    ASSERT_EQ(write_u32(0x1010, 1, kSaveSignature), AbortCode::None);
    // A crash during the next save leaves at most a partial temporary file beside the store.
    write_file(fs::path(path()) += ".tmp", Bytes{'E', 'P', 'O'});
    EXPECT_EQ(store_.load_stored_values().status, StoredValuesStatus::Applied);
    EXPECT_EQ(od_.get_as<std::int32_t>(0x2080, 1), 25000);
}

struct SignatureCase {
    const char* what;
    std::uint16_t index;
    std::uint32_t value;
};

class StoreRestoreSignature : public StoreRestore,
                              public testing::WithParamInterface<SignatureCase> {};

TEST_P(StoreRestoreSignature, AnythingButTheSignatureIsRefusedWithTransferOrStore) {
    change_every_value();
    ASSERT_EQ(write_u32(0x1010, 1, kSaveSignature), AbortCode::None);
    const Bytes stored = read_file(path());
    change_every_value();
    od_.set_as<std::uint16_t>(0x1017, 0, 1);

    EXPECT_EQ(write_u32(GetParam().index, 1, GetParam().value), AbortCode::TransferOrStore)
        << GetParam().what;
    EXPECT_EQ(read_file(path()), stored) << "neither stored nor restored";
}

INSTANTIATE_TEST_SUITE_P(Table, StoreRestoreSignature,
                         testing::Values(SignatureCase{"save_with_zero", 0x1010, 0},
                                         SignatureCase{"save_with_load", 0x1010, kLoadSignature},
                                         SignatureCase{"save_upper_case", 0x1010, 0x4556'4153},
                                         SignatureCase{"save_byte_swapped", 0x1010, 0x7361'7665},
                                         SignatureCase{"restore_with_save", 0x1011, kSaveSignature},
                                         SignatureCase{"restore_with_ones", 0x1011, 0xFFFF'FFFF}),
                         [](const auto& param_info) { return std::string(param_info.param.what); });

TEST_F(StoreRestore, SignatureOfTheWrongLengthIsALengthError) {
    EXPECT_EQ(od_.write(0x1010, 1, Bytes{'s', 'a', 'v'}), AbortCode::LengthTooLow);
    EXPECT_EQ(od_.write(0x1011, 1, Bytes{'l', 'o', 'a', 'd', 0}), AbortCode::LengthTooHigh);
    EXPECT_EQ(od_.write(0x1010, 2, encode(kSaveSignature)), AbortCode::SubIndexDoesNotExist);
}

TEST_F(StoreRestore, SignaturesAreTheLettersLowestByteFirst) {
    EXPECT_EQ(encode(kSaveSignature), (Bytes{'s', 'a', 'v', 'e'}));
    EXPECT_EQ(encode(kLoadSignature), (Bytes{'l', 'o', 'a', 'd'}));
}

TEST_F(StoreRestore, ReadingGivesTheCapabilityBitsEvenAfterACommand) {
    ASSERT_EQ(write_u32(0x1010, 1, kSaveSignature), AbortCode::None);
    ASSERT_EQ(write_u32(0x1011, 1, kLoadSignature), AbortCode::None);
    Bytes out;
    ASSERT_EQ(od_.read(0x1010, 1, out), AbortCode::None);
    EXPECT_EQ(decode<std::uint32_t>(out), 1U) << "saves on command";
    ASSERT_EQ(od_.read(0x1011, 1, out), AbortCode::None);
    EXPECT_EQ(decode<std::uint32_t>(out), 1U) << "restores defaults";
    EXPECT_EQ(od_.get_as<std::uint8_t>(0x1010, 0), 1);
    EXPECT_EQ(od_.get_as<std::uint8_t>(0x1011, 0), 1);
    EXPECT_EQ(od_.find(0x1010)->code, ObjectCode::Array);
}

TEST_F(StoreRestore, RestoreAppliesTheDefaultsOnlyAfterTheNextReset) {
    change_every_value();
    ASSERT_EQ(write_u32(0x1010, 1, kSaveSignature), AbortCode::None);
    ASSERT_EQ(write_u32(0x1011, 1, kLoadSignature), AbortCode::None);
    EXPECT_EQ(od_.get_as<std::uint16_t>(0x1017, 0), 100) << "CiA 301 7.5.2.14: not at once";

    const StoredValuesReport report = store_.load_stored_values();

    EXPECT_EQ(report.status, StoredValuesStatus::NoneStored);
    EXPECT_FALSE(report.refused());
    EXPECT_EQ(od_.get_as<std::uint16_t>(0x1017, 0), 0);
    EXPECT_EQ(od_.get(0x1008, 0), encode_string("EPOS2"));
    EXPECT_EQ(od_.get_as<std::int32_t>(0x2080, 1), -1);
}

TEST_F(StoreRestore, SaveAfterRestoreStoresTheCurrentValuesAgain) {
    change_every_value();
    ASSERT_EQ(write_u32(0x1011, 1, kLoadSignature), AbortCode::None);
    ASSERT_EQ(write_u32(0x1010, 1, kSaveSignature), AbortCode::None);
    EXPECT_EQ(store_.load_stored_values().status, StoredValuesStatus::Applied);
    EXPECT_EQ(od_.get_as<std::uint16_t>(0x1017, 0), 100);
}

TEST_F(StoreRestore, RestoreIsRefusedWithTheCodeTheDeviceGives) {
    change_every_value();
    ASSERT_EQ(write_u32(0x1010, 1, kSaveSignature), AbortCode::None);
    restore_refusal_ = AbortCode::DeviceState; // EPOS2 8.2.9: e.g. not in "Power Disable"
    EXPECT_EQ(write_u32(0x1011, 1, kLoadSignature), AbortCode::DeviceState);
    EXPECT_EQ(store_.load_stored_values().status, StoredValuesStatus::Applied);
}

TEST_F(StoreRestore, PowerUpWithoutAStoreUsesTheDefaults) {
    change_every_value();
    const StoredValuesReport report = store_.load_stored_values();
    EXPECT_EQ(report.status, StoredValuesStatus::NoneStored);
    EXPECT_EQ(od_.get_as<std::uint16_t>(0x6041, 0), 0x40);
    EXPECT_EQ(od_.get_as<float>(0x2080, 2), 0.5F);
}

TEST_F(StoreRestore, LoadingDoesNotTellListeners) {
    ASSERT_EQ(write_u32(0x1010, 1, kSaveSignature), AbortCode::None);
    int changes = 0;
    od_.on_change(0x1017, [&](auto, auto) { ++changes; });
    store_.load_stored_values();
    EXPECT_EQ(changes, 0);
}

TEST_F(StoreRestore, AFailedStoreIsAHardwareError) {
    ObjectDictionary od;
    build(od);
    ParameterStore store(od, directory_ / "missing-directory" / "parameters.bin");
    add_store_restore_objects(od, store);
    EXPECT_EQ(od.write(0x1010, 1, encode(kSaveSignature)), AbortCode::HardwareError);
}

// Damage of every kind: the defaults apply and the report says why, naming the file.
struct DamageCase {
    const char* what;
    void (*damage)(Bytes&);
};

class StoreRestoreDamage : public StoreRestore, public testing::WithParamInterface<DamageCase> {};

TEST_P(StoreRestoreDamage, ADamagedStoreIsReportedAndTheDefaultsApply) {
    change_every_value();
    ASSERT_EQ(write_u32(0x1010, 1, kSaveSignature), AbortCode::None);
    Bytes content = read_file(path());
    GetParam().damage(content);
    write_file(path(), content);

    const StoredValuesReport report = store_.load_stored_values();

    EXPECT_EQ(report.status, StoredValuesStatus::Corrupt);
    EXPECT_TRUE(report.refused());
    EXPECT_NE(report.detail.find(path().string()), std::string::npos) << report.detail;
    EXPECT_EQ(od_.get_as<std::uint16_t>(0x1017, 0), 0);
    EXPECT_EQ(od_.get_as<std::int32_t>(0x2080, 1), -1);
}

INSTANTIATE_TEST_SUITE_P(Table, StoreRestoreDamage,
                         testing::Values(DamageCase{"flipped_bit_in_a_value",
                                                    [](Bytes& b) {
                                                        b[b.size() / 2] ^= 1;
                                                    }},
                                         DamageCase{"flipped_bit_in_the_checksum",
                                                    [](Bytes& b) {
                                                        b.back() ^= 0x80;
                                                    }},
                                         DamageCase{"truncated",
                                                    [](Bytes& b) {
                                                        b.erase(b.end() - 5, b.end());
                                                    }},
                                         DamageCase{"empty",
                                                    [](Bytes& b) {
                                                        b.clear();
                                                    }},
                                         DamageCase{"trailing_byte",
                                                    [](Bytes& b) {
                                                        b.push_back(0);
                                                    }},
                                         DamageCase{"another_file",
                                                    [](Bytes& b) {
                                                        b.assign(64, 'x');
                                                    }}),
                         [](const auto& param_info) { return std::string(param_info.param.what); });

TEST_F(StoreRestore, AStoreOfAnotherLayoutIsNotApplied) {
    // The same file written by a dictionary whose persistent objects differ.
    ObjectDictionary other;
    build(other);
    other.add_variable(0x2081, "Extra", DataType::Unsigned8, Access::ReadWrite, {7}).persistent =
        true;
    other.set_as<std::uint16_t>(0x1017, 0, 100);
    ParameterStore other_store(other, path());
    ASSERT_EQ(other_store.save(), AbortCode::None);
    ASSERT_NE(other_store.layout_id(), store_.layout_id());

    const StoredValuesReport report = store_.load_stored_values();

    EXPECT_EQ(report.status, StoredValuesStatus::LayoutMismatch);
    EXPECT_TRUE(report.refused());
    EXPECT_EQ(od_.get_as<std::uint16_t>(0x1017, 0), 0);
}

TEST_F(StoreRestore, LayoutIdDependsOnPersistentTypesNotOnNamesOrVolatileObjects) {
    ObjectDictionary renamed;
    build(renamed);
    renamed.find(0x1017, 0)->name = "Heartbeat";
    renamed.add_variable(0x3000, "Volatile", DataType::Unsigned8, Access::ReadWrite, {0});
    EXPECT_EQ(ParameterStore(renamed, path()).layout_id(), store_.layout_id());

    ObjectDictionary retyped;
    build(retyped);
    retyped.find(0x2080, 1)->type = DataType::Unsigned32;
    EXPECT_NE(ParameterStore(retyped, path()).layout_id(), store_.layout_id());
}

// EPOS2 firmware specification 8.2.9, table 8-73: 0x1011 sub 5 "Restore Default PDO COB-IDs".
class RestorePdoCobIds : public StoreRestore {
protected:
    void SetUp() override {
        StoreRestore::SetUp();
        for (std::uint16_t n = 0; n < 4; ++n) {
            add_pdo(static_cast<std::uint16_t>(0x1400 + n), 0x8000'0000U | (0x211U + n));
            add_pdo(static_cast<std::uint16_t>(0x1800 + n), 0x4000'0000U | (0x191U + n));
        }
        add_pdo(0x1404, 0x8000'0123U); // no predefined COB-ID: kept
        add_restore_pdo_cob_ids_object(od_, store_, [this] { return node_id_; },
                                       {.restore_permitted = [this] {
                                           return restore_refusal_;
                                       }});
    }
    void add_pdo(std::uint16_t index, std::uint32_t cob_id) {
        od_.add_object(index, "PDO parameter", ObjectCode::Record);
        od_.add_sub(index, 1, "COB-ID", DataType::Unsigned32, Access::ReadWrite, encode(cob_id))
            .persistent = true;
    }
    NodeId node_id_ = 5;
};

TEST_F(RestorePdoCobIds, TakeEffectAfterSavingAndRestarting) {
    ASSERT_EQ(write_u32(0x1011, 5, kLoadSignature), AbortCode::None);
    EXPECT_EQ(od_.get_as<std::uint32_t>(0x1400, 1), 0x8000'0211U) << "not at once";
    node_id_ = 7; // the node-ID at the time of the command counts, not at the save
    ASSERT_EQ(write_u32(0x1010, 1, kSaveSignature), AbortCode::None);
    ASSERT_EQ(store_.load_stored_values().status, StoredValuesStatus::Applied);

    const std::uint32_t expected[] = {0x8000'0205, 0x8000'0305, 0x8000'0405, 0x8000'0505,
                                      0x4000'0185, 0x4000'0285, 0x4000'0385, 0x4000'0485};
    for (std::uint16_t n = 0; n < 4; ++n) {
        EXPECT_EQ(od_.get_as<std::uint32_t>(0x1400 + n, 1), expected[n]) << "RPDO" << n + 1;
        EXPECT_EQ(od_.get_as<std::uint32_t>(0x1800 + n, 1), expected[4 + n]) << "TPDO" << n + 1;
    }
    EXPECT_EQ(od_.get_as<std::uint32_t>(0x1404, 1), 0x8000'0123U);
}

TEST_F(RestorePdoCobIds, OnlyTheNextSaveCalculatesThem) {
    ASSERT_EQ(write_u32(0x1011, 5, kLoadSignature), AbortCode::None);
    ASSERT_EQ(write_u32(0x1010, 1, kSaveSignature), AbortCode::None);
    od_.set_as<std::uint32_t>(0x1800, 1, 0x4000'0222U);
    ASSERT_EQ(write_u32(0x1010, 1, kSaveSignature), AbortCode::None);
    store_.load_stored_values();
    EXPECT_EQ(od_.get_as<std::uint32_t>(0x1800, 1), 0x4000'0222U);
}

TEST_F(RestorePdoCobIds, WrongSignatureOrStateIsRefused) {
    EXPECT_EQ(write_u32(0x1011, 5, kSaveSignature), AbortCode::TransferOrStore);
    restore_refusal_ = AbortCode::WrongNmtState;
    EXPECT_EQ(write_u32(0x1011, 5, kLoadSignature), AbortCode::WrongNmtState);
}

TEST_F(RestorePdoCobIds, SubIndexZeroGivesTheNumberOfEntriesAsTable8_73) {
    EXPECT_EQ(od_.get_as<std::uint8_t>(0x1011, 0), 2);
    Bytes out;
    EXPECT_EQ(od_.read(0x1011, 5, out), AbortCode::None);
    EXPECT_EQ(decode<std::uint32_t>(out), 1U);
}

} // namespace
} // namespace eposp::canopen

#include "eposp/canopen/eds_export.hpp"
#include "eposp/canopen/eds_import.hpp"
#include "eposp/canopen/parameter_store.hpp"
#include "eposp/canopen/store_restore_objects.hpp"

#include <cctype>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace eposp::canopen {
namespace {

// A dictionary with every kind of object an EPOS2-like device has.
ObjectDictionary device_dictionary() {
    ObjectDictionary od;
    od.add_variable(0x1000, "Device type", DataType::Unsigned32, Access::ReadOnly,
                    encode<std::uint32_t>(0x0002'0192));
    od.add_variable(0x1001, "Error register", DataType::Unsigned8, Access::ReadOnly, {0});
    od.add_object(0x1003, "Pre-defined error field", ObjectCode::Array);
    for (std::uint8_t sub = 1; sub <= 5; ++sub) {
        od.add_sub(0x1003, sub, "Standard error field", DataType::Unsigned32, Access::ReadOnly,
                   encode<std::uint32_t>(0));
    }
    SubObject& errors = *od.find(0x1003, 0);
    errors.name = "Number of errors";
    errors.access = Access::ReadWrite;
    errors.default_value = {0};
    errors.value = {0};
    od.add_variable(0x1008, "Manufacturer device name", DataType::VisibleString, Access::Const,
                    encode_string("EPOS2 24/5"));
    od.add_variable(0x1017, "Producer heartbeat time", DataType::Unsigned16, Access::ReadWrite,
                    encode<std::uint16_t>(0));
    od.add_object(0x1018, "Identity Object", ObjectCode::Record);
    od.add_sub(0x1018, 1, "Vendor-ID", DataType::Unsigned32, Access::ReadOnly,
               encode<std::uint32_t>(0xFB));
    od.add_sub(0x1018, 2, "Product code", DataType::Unsigned32, Access::ReadOnly,
               encode<std::uint32_t>(0x6050'0000));
    od.add_object(0x1400, "Receive PDO 1 Parameter", ObjectCode::Record);
    od.add_sub(0x1400, 1, "COB-ID used by RPDO 1", DataType::Unsigned32, Access::ReadWrite,
               encode<std::uint32_t>(0x201));
    od.add_sub(0x1400, 2, "Transmission type RPDO 1", DataType::Unsigned8, Access::ReadWrite,
               {0xFF});
    od.add_object(0x1800, "Transmit PDO 1 Parameter", ObjectCode::Record);
    od.add_sub(0x1800, 1, "COB-ID used by TPDO 1", DataType::Unsigned32, Access::ReadWrite,
               encode<std::uint32_t>(0x4000'0181));
    od.add_object(0x1801, "Transmit PDO 2 Parameter", ObjectCode::Record);
    od.add_sub(0x1801, 1, "COB-ID used by TPDO 2", DataType::Unsigned32, Access::ReadWrite,
               encode<std::uint32_t>(0x4000'0281));
    od.add_variable(0x1F51, "Program control", DataType::Unsigned8, Access::ReadWrite, {0});
    od.add_variable(0x1F50, "Program data", DataType::Domain, Access::WriteOnly, {0xDE, 0xAD});
    od.find(0x1F50)->code = ObjectCode::Domain;

    SubObject& velocity = od.add_variable(0x2001, "Max velocity", DataType::Integer16,
                                          Access::ReadWrite, encode<std::int16_t>(-300));
    velocity.low_limit = encode<std::int16_t>(-32000);
    velocity.high_limit = encode<std::int16_t>(32000);
    SubObject& gain =
        od.add_variable(0x2002, "Gain", DataType::Real32, Access::ReadWrite, encode(0.1F));
    gain.low_limit = encode(-2.5F);
    gain.high_limit = encode(1e10F);
    od.add_variable(0x2003, "Position offset", DataType::Integer24, Access::ReadWrite,
                    Bytes{0x00, 0x00, 0x80});
    od.add_variable(0x2004, "Counter", DataType::Unsigned64, Access::ReadOnly,
                    encode(std::numeric_limits<std::uint64_t>::max()));
    od.add_variable(0x2005, "Enable", DataType::Boolean, Access::ReadWrite, {1});
    od.add_variable(0x2006, "Serial", DataType::OctetString, Access::ReadOnly,
                    Bytes{0x01, 0xAB, 0x00});
    od.add_variable(0x2007, "Precise", DataType::Real64, Access::ReadWrite, encode(-1.0 / 3));
    od.add_variable(0x2008, "Empty name", DataType::VisibleString, Access::ReadWrite, {});
    od.add_variable(0x2009, "Time", DataType::TimeOfDay, Access::ReadWrite,
                    Bytes{1, 2, 3, 4, 5, 6});
    od.add_variable(0x6040, "Controlword", DataType::Unsigned16, Access::ReadWriteOutput,
                    encode<std::uint16_t>(0))
        .pdo_mappable = true;
    od.add_variable(0x6041, "Statusword", DataType::Unsigned16, Access::ReadWriteInput,
                    encode<std::uint16_t>(0))
        .pdo_mappable = true;
    return od;
}

DeviceInfo device_info() {
    DeviceInfo info;
    info.file.file_name = "epos2.eds";
    info.file.file_version = 3;
    info.file.file_revision = 2;
    info.file.description = "EPOS2 positioning controller";
    info.file.creation_time = "09:00AM";
    info.file.creation_date = "01-15-2024";
    info.file.created_by = "eposp";
    info.file.comments = {"Simulated drive", "second line"};
    info.vendor_name = "maxon motor ag";
    info.vendor_number = 0xFB;
    info.product_name = "EPOS2 24/5";
    info.product_number = 0x6050'0000;
    info.revision_number = 0x2126'0000;
    info.order_code = "367676";
    info.baud_rates_kbit = {20, 50, 125, 250, 500, 800, 1000};
    info.simple_boot_up_slave = true;
    info.lss_supported = true;
    info.dummy_usage = {2, 3, 4, 5, 6, 7};
    return info;
}

void expect_same_subobjects(const ObjectDictionary& expected, const ObjectDictionary& actual) {
    ASSERT_EQ(expected.objects().size(), actual.objects().size());
    for (const auto& [index, object] : expected.objects()) {
        const Object* other = actual.find(index);
        ASSERT_NE(other, nullptr) << std::hex << index;
        EXPECT_EQ(other->name, object.name);
        EXPECT_EQ(other->code, object.code) << std::hex << index;
        ASSERT_EQ(other->subs.size(), object.subs.size()) << std::hex << index;
        for (const auto& [sub_index, sub] : object.subs) {
            const SubObject& got = other->subs.at(sub_index);
            const std::string where = fmt::format("{:04X}sub{:X}", index, sub_index);
            EXPECT_EQ(got.name, sub.name) << where;
            EXPECT_EQ(got.type, sub.type) << where;
            EXPECT_EQ(got.access, sub.access) << where;
            EXPECT_EQ(got.pdo_mappable, sub.pdo_mappable) << where;
            EXPECT_EQ(got.default_value, sub.default_value) << where;
            EXPECT_EQ(got.value, sub.default_value) << where;
            EXPECT_EQ(got.low_limit, sub.low_limit) << where;
            EXPECT_EQ(got.high_limit, sub.high_limit) << where;
        }
    }
}

TEST(Eds, ExportImportExportGivesTheSameText) {
    const ObjectDictionary od = device_dictionary();
    const std::string first = export_eds(od, device_info());

    const auto imported = import_eds(first, "epos2.eds");
    ASSERT_TRUE(imported.ok()) << imported.error();
    EXPECT_EQ(export_eds(imported->dictionary, imported->device), first);
    EXPECT_EQ(imported->device, device_info());
    expect_same_subobjects(od, imported->dictionary);
}

TEST(Eds, StoreAndRestoreObjectsRoundTrip) {
    ObjectDictionary od = device_dictionary();
    ParameterStore store(od, "unused.bin");
    add_store_restore_objects(od, store);
    const std::string text = export_eds(od, device_info());
    EXPECT_NE(text.find("[1010sub1]\nParameterName=Save all Parameters\nObjectType=0x7\n"
                        "DataType=0x0007\nAccessType=rw\nDefaultValue=0x00000001\n"),
              std::string::npos);
    const auto imported = import_eds(text, "epos2.eds");
    ASSERT_TRUE(imported.ok()) << imported.error();
    EXPECT_EQ(export_eds(imported->dictionary, imported->device), text);
}

TEST(Eds, ExportWritesCia306Sections) {
    ObjectDictionary od;
    od.add_variable(0x1000, "Device type", DataType::Unsigned32, Access::ReadOnly,
                    encode<std::uint32_t>(0x0002'0192));
    od.add_object(0x1018, "Identity", ObjectCode::Record);
    od.add_sub(0x1018, 1, "Vendor-ID", DataType::Unsigned32, Access::ReadOnly,
               encode<std::uint32_t>(0xFB));
    od.add_object(0x1800, "TPDO1", ObjectCode::Record);
    SubObject& limited = od.add_variable(0x2000, "Limited", DataType::Integer8, Access::ReadWrite,
                                         encode<std::int8_t>(-1));
    limited.low_limit = encode<std::int8_t>(-100);
    limited.high_limit = encode<std::int8_t>(100);
    od.add_variable(0x6041, "Statusword", DataType::Unsigned16, Access::ReadWriteInput,
                    encode<std::uint16_t>(0))
        .pdo_mappable = true;
    DeviceInfo info;
    info.vendor_name = "maxon motor ag";
    info.vendor_number = 0xFB;
    info.baud_rates_kbit = {1000};
    info.dummy_usage = {5};

    EXPECT_EQ(export_eds(od, info), R"([FileInfo]
FileName=
FileVersion=1
FileRevision=0
EDSVersion=4.0
Description=
CreationTime=
CreationDate=
CreatedBy=
ModificationTime=
ModificationDate=
ModifiedBy=

[DeviceInfo]
VendorName=maxon motor ag
VendorNumber=0x000000FB
ProductName=
ProductNumber=0x00000000
RevisionNumber=0x00000000
OrderCode=
BaudRate_10=0
BaudRate_20=0
BaudRate_50=0
BaudRate_125=0
BaudRate_250=0
BaudRate_500=0
BaudRate_800=0
BaudRate_1000=1
SimpleBootUpMaster=0
SimpleBootUpSlave=0
Granularity=8
DynamicChannelsSupported=0
GroupMessaging=0
NrOfRxPDO=0
NrOfTxPDO=1
LSS_Supported=0

[DummyUsage]
Dummy0001=0
Dummy0002=0
Dummy0003=0
Dummy0004=0
Dummy0005=1
Dummy0006=0
Dummy0007=0

[MandatoryObjects]
SupportedObjects=2
1=0x1000
2=0x1018

[OptionalObjects]
SupportedObjects=2
1=0x1800
2=0x6041

[ManufacturerObjects]
SupportedObjects=1
1=0x2000

[1000]
ParameterName=Device type
ObjectType=0x7
DataType=0x0007
AccessType=ro
DefaultValue=0x00020192
PDOMapping=0

[1018]
ParameterName=Identity
ObjectType=0x9
SubNumber=0x2

[1018sub0]
ParameterName=Highest sub-index supported
ObjectType=0x7
DataType=0x0005
AccessType=ro
DefaultValue=0x01
PDOMapping=0

[1018sub1]
ParameterName=Vendor-ID
ObjectType=0x7
DataType=0x0007
AccessType=ro
DefaultValue=0x000000FB
PDOMapping=0

[1800]
ParameterName=TPDO1
ObjectType=0x9
SubNumber=0x1

[1800sub0]
ParameterName=Highest sub-index supported
ObjectType=0x7
DataType=0x0005
AccessType=ro
DefaultValue=0x00
PDOMapping=0

[2000]
ParameterName=Limited
ObjectType=0x7
DataType=0x0002
LowLimit=-100
HighLimit=100
AccessType=rw
DefaultValue=-1
PDOMapping=0

[6041]
ParameterName=Statusword
ObjectType=0x7
DataType=0x0006
AccessType=rwr
DefaultValue=0x0000
PDOMapping=1
)");
}

// In the style of a vendor's file: CR LF, comments, keys in any case, $NODEID, octal, compact
// arrays, data type entries in the optional list, tool sections the import does not know.
constexpr std::string_view kVendorEds = "; EDS file for a positioning controller\r\n"
                                        "[FileInfo]\r\n"
                                        "FileName=vendor.eds\r\n"
                                        "FileVersion=2\r\n"
                                        "FileRevision=7\r\n"
                                        "EDSVersion=4.0\r\n"
                                        "Description=Positioning Controller\r\n"
                                        "CreationTime=10:15AM\r\n"
                                        "CreationDate=03-22-2010\r\n"
                                        "CreatedBy=Vendor\r\n"
                                        "\r\n"
                                        "[DeviceInfo]\r\n"
                                        "VendorName=maxon motor ag\r\n"
                                        "VendorNumber=0x000000FB\r\n"
                                        "ProductName=EPOS2\r\n"
                                        "ProductNumber=1615855616\r\n"
                                        "RevisionNumber=0x21260000\r\n"
                                        "OrderCode=\r\n"
                                        "baudrate_125=1\r\n"
                                        "BaudRate_1000=1\r\n"
                                        "BaudRate_800=0\r\n"
                                        "SimpleBootUpSlave=1\r\n"
                                        "Granularity=8\r\n"
                                        "NrOfRxPDO=1\r\n"
                                        "NrOfTxPDO=1\r\n"
                                        "LSS_Supported=1\r\n"
                                        "\r\n"
                                        "[DummyUsage]\r\n"
                                        "Dummy0002=1\r\n"
                                        "Dummy0005=1\r\n"
                                        "\r\n"
                                        "[Comments]\r\n"
                                        "Lines=1\r\n"
                                        "Line1=hand-written for the test\r\n"
                                        "\r\n"
                                        "[MandatoryObjects]\r\n"
                                        "SupportedObjects=3\r\n"
                                        "1=0x1000\r\n"
                                        "2=0x1001\r\n"
                                        "3=0x1018\r\n"
                                        "\r\n"
                                        "[OptionalObjects]\r\n"
                                        "SupportedObjects=6\r\n"
                                        "1=0x0002\r\n"
                                        "2=0x1003\r\n"
                                        "3=0x1014\r\n"
                                        "4=0x1400\r\n"
                                        "5=0x1F50\r\n"
                                        "6=24641\r\n"
                                        "\r\n"
                                        "[ManufacturerObjects]\r\n"
                                        "SupportedObjects=3\r\n"
                                        "1=0x2000\r\n"
                                        "2=0x2080\r\n"
                                        "3=0101001\r\n"
                                        "\r\n"
                                        "[0002]\r\n"
                                        "ParameterName=INTEGER8\r\n"
                                        "ObjectType=0x5\r\n"
                                        "DataType=0x0007\r\n"
                                        "AccessType=ro\r\n"
                                        "DefaultValue=8\r\n"
                                        "\r\n"
                                        "[1000]\r\n"
                                        "parametername=Device Type\r\n"
                                        "OBJECTTYPE=0x07\r\n"
                                        "DataType=0x0007\r\n"
                                        "AccessType=RO\r\n"
                                        "DefaultValue=0x00020192\r\n"
                                        "PDOMapping=0\r\n"
                                        "\r\n"
                                        "[1001]\r\n"
                                        "ParameterName=Error Register\r\n"
                                        "DataType=0x0005\r\n"
                                        "AccessType=ro\r\n"
                                        "PDOMapping=1\r\n"
                                        "\r\n"
                                        "[1003]\r\n"
                                        "ParameterName=Error History\r\n"
                                        "ObjectType=0x8\r\n"
                                        "DataType=0x0007\r\n"
                                        "AccessType=ro\r\n"
                                        "DefaultValue=0\r\n"
                                        "CompactSubObj=3\r\n"
                                        "\r\n"
                                        "[1003Name]\r\n"
                                        "NrOfEntries=1\r\n"
                                        "1=Newest Error\r\n"
                                        "\r\n"
                                        "[1014]\r\n"
                                        "ParameterName=COB-ID EMCY\r\n"
                                        "ObjectType=0x7\r\n"
                                        "DataType=0x0007\r\n"
                                        "AccessType=rw\r\n"
                                        "DefaultValue=$NODEID+0x80\r\n"
                                        "PDOMapping=0\r\n"
                                        "\r\n"
                                        "[1018]\r\n"
                                        "ParameterName=Identity Object\r\n"
                                        "ObjectType=0x9\r\n"
                                        "SubNumber=3\r\n"
                                        "\r\n"
                                        "[1018sub0]\r\n"
                                        "ParameterName=Number of entries\r\n"
                                        "ObjectType=0x7\r\n"
                                        "DataType=0x0005\r\n"
                                        "AccessType=ro\r\n"
                                        "DefaultValue=4\r\n"
                                        "PDOMapping=0\r\n"
                                        "\r\n"
                                        "[1018sub1]\r\n"
                                        "ParameterName=Vendor ID\r\n"
                                        "ObjectType=0x7\r\n"
                                        "DataType=0x0007\r\n"
                                        "AccessType=ro\r\n"
                                        "DefaultValue=0x000000FB\r\n"
                                        "PDOMapping=0\r\n"
                                        "\r\n"
                                        "[1018SUB4]\r\n"
                                        "ParameterName=Serial number\r\n"
                                        "ObjectType=0x7\r\n"
                                        "DataType=0x0007\r\n"
                                        "AccessType=ro\r\n"
                                        "DefaultValue=\r\n"
                                        "PDOMapping=0\r\n"
                                        "\r\n"
                                        "[1400]\r\n"
                                        "ParameterName=Receive PDO 1 Parameter\r\n"
                                        "ObjectType=0x9\r\n"
                                        "SubNumber=2\r\n"
                                        "\r\n"
                                        "[1400sub0]\r\n"
                                        "ParameterName=Highest SubIndex\r\n"
                                        "ObjectType=0x7\r\n"
                                        "DataType=0x0005\r\n"
                                        "AccessType=ro\r\n"
                                        "DefaultValue=1\r\n"
                                        "\r\n"
                                        "[1400sub1]\r\n"
                                        "ParameterName=COB-ID used by RPDO 1\r\n"
                                        "ObjectType=0x7\r\n"
                                        "DataType=0x0007\r\n"
                                        "AccessType=rw\r\n"
                                        "DefaultValue= 0x200 + $NodeId \r\n"
                                        "PDOMapping=0\r\n"
                                        "\r\n"
                                        "[1F50]\r\n"
                                        "ParameterName=Program data\r\n"
                                        "ObjectType=0x2\r\n"
                                        "\r\n"
                                        "[2000]\r\n"
                                        "ParameterName=Node ID\r\n"
                                        "ObjectType=0x7\r\n"
                                        "DataType=0x0005\r\n"
                                        "AccessType=rw\r\n"
                                        "DefaultValue=$NODEID\r\n"
                                        "LowLimit=1\r\n"
                                        "HighLimit=127\r\n"
                                        "PDOMapping=0\r\n"
                                        "\r\n"
                                        "[2080]\r\n"
                                        "ParameterName=Home offset\r\n"
                                        "ObjectType=0x7\r\n"
                                        "DataType=0x0004\r\n"
                                        "AccessType=rw\r\n"
                                        "DefaultValue=0xFFFFFFF6\r\n"
                                        "LowLimit=-2147483648\r\n"
                                        "HighLimit=0x7FFFFFFF\r\n"
                                        "PDOMapping=0\r\n"
                                        "\r\n"
                                        "[2081]\r\n"
                                        "ParameterName=Not listed, so not imported\r\n"
                                        "ObjectType=0x7\r\n"
                                        "\r\n"
                                        "[8201]\r\n"
                                        "ParameterName=Octal index\r\n"
                                        "ObjectType=0x7\r\n"
                                        "DataType=0x0006\r\n"
                                        "AccessType=rww\r\n"
                                        "DefaultValue=017\r\n"
                                        "PDOMapping=1\r\n"
                                        "\r\n"
                                        "[6041]\r\n"
                                        "ParameterName=Statusword\r\n"
                                        "ObjectType=0x7\r\n"
                                        "DataType=0x0006\r\n"
                                        "AccessType=ro\r\n"
                                        "DefaultValue=0\r\n"
                                        "PDOMapping=1\r\n"
                                        "\r\n"
                                        "[ToolSpecific]\r\n"
                                        "Anything=goes\r\n";

TEST(Eds, ImportsAVendorStyleFile) {
    const auto imported = import_eds(kVendorEds, "vendor.eds", NodeId{3});
    ASSERT_TRUE(imported.ok()) << imported.error();
    const ObjectDictionary& od = imported->dictionary;
    const DeviceInfo& device = imported->device;

    EXPECT_EQ(device.file.file_name, "vendor.eds");
    EXPECT_EQ(device.file.file_version, 2);
    EXPECT_EQ(device.file.file_revision, 7);
    EXPECT_EQ(device.file.creation_date, "03-22-2010");
    EXPECT_EQ(device.file.comments, std::vector<std::string>{"hand-written for the test"});
    EXPECT_EQ(device.vendor_name, "maxon motor ag");
    EXPECT_EQ(device.vendor_number, 0xFBU);
    EXPECT_EQ(device.product_number, 1615855616U);
    EXPECT_EQ(device.revision_number, 0x2126'0000U);
    EXPECT_EQ(device.baud_rates_kbit, (std::set<std::uint16_t>{125, 1000}));
    EXPECT_TRUE(device.simple_boot_up_slave);
    EXPECT_FALSE(device.simple_boot_up_master);
    EXPECT_TRUE(device.lss_supported);
    EXPECT_EQ(device.dummy_usage, (std::set<std::uint16_t>{2, 5}));

    EXPECT_EQ(od.objects().size(), 11U) << "the listed objects with values";
    EXPECT_EQ(od.find(0x0002), nullptr) << "a data type definition holds no value";
    EXPECT_EQ(od.find(0x2081), nullptr);
    EXPECT_EQ(od.find(0x1000)->name, "Device Type");
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1000, 0), 0x0002'0192U);
    EXPECT_EQ(od.find(0x1001, 0)->access, Access::ReadOnly);
    EXPECT_TRUE(od.find(0x1001, 0)->pdo_mappable);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x1001, 0), 0) << "no DefaultValue: zero";

    // CompactSubObj=3: sub-indices 1..3 with the object's keys, names from [1003Name].
    const Object& history = *od.find(0x1003);
    EXPECT_EQ(history.code, ObjectCode::Array);
    ASSERT_EQ(history.subs.size(), 4U);
    EXPECT_EQ(history.subs.at(0).name, "NrOfObjects");
    EXPECT_EQ(od.get_as<std::uint8_t>(0x1003, 0), 3);
    EXPECT_EQ(history.subs.at(1).name, "Newest Error");
    EXPECT_EQ(history.subs.at(2).name, "Error History2");
    EXPECT_EQ(history.subs.at(3).type, DataType::Unsigned32);
    EXPECT_EQ(history.subs.at(3).access, Access::ReadOnly);

    EXPECT_EQ(od.get_as<std::uint32_t>(0x1014, 0), 0x83U) << "$NODEID+0x80";
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1400, 1), 0x203U) << "0x200 + $NodeId";
    EXPECT_EQ(od.get_as<std::uint8_t>(0x2000, 0), 3) << "$NODEID";
    EXPECT_EQ(od.find(0x1400, 0)->name, "Highest SubIndex");

    const Object& identity = *od.find(0x1018);
    EXPECT_EQ(identity.code, ObjectCode::Record);
    EXPECT_EQ(identity.subs.size(), 3U);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x1018, 0), 4) << "sub 0 as the file says";
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1018, 4), 0U) << "empty DefaultValue: zero";
    EXPECT_EQ(od.find(0x1018, 4)->name, "Serial number");

    EXPECT_EQ(od.find(0x1F50)->code, ObjectCode::Domain);
    EXPECT_EQ(od.find(0x1F50, 0)->type, DataType::Domain);
    EXPECT_EQ(od.find(0x1F50, 0)->access, Access::ReadWrite);

    EXPECT_EQ(od.get_as<std::int32_t>(0x2080, 0), -10) << "hex as two's complement";
    EXPECT_EQ(od.find(0x2080, 0)->low_limit, encode(std::numeric_limits<std::int32_t>::min()));
    EXPECT_EQ(od.find(0x2080, 0)->high_limit, encode(std::numeric_limits<std::int32_t>::max()));
    EXPECT_EQ(od.get_as<std::uint16_t>(0x8201, 0), 15) << "octal 017, index in octal 0101001";
    EXPECT_EQ(od.find(0x8201, 0)->access, Access::ReadWriteOutput);

    // The imported dictionary enforces the file's limits.
    ObjectDictionary copy = od;
    EXPECT_EQ(copy.write(0x2000, 0, Bytes{128}), AbortCode::ValueTooHigh);
    EXPECT_EQ(copy.write(0x2000, 0, Bytes{0}), AbortCode::ValueTooLow);
}

TEST(Eds, ImportOfAVendorFileExportsAndReadsBackUnchanged) {
    const auto imported = import_eds(kVendorEds, "vendor.eds", NodeId{3});
    ASSERT_TRUE(imported.ok()) << imported.error();
    const std::string text = export_eds(imported->dictionary, imported->device);
    const auto again = import_eds(text, "exported.eds");
    ASSERT_TRUE(again.ok()) << again.error();
    EXPECT_EQ(export_eds(again->dictionary, again->device), text);
}

TEST(Eds, DcfParameterValueBecomesTheCurrentValue) {
    const std::string dcf = "[OptionalObjects]\nSupportedObjects=1\n1=0x1017\n"
                            "[1017]\nParameterName=Producer heartbeat time\nDataType=0x0006\n"
                            "AccessType=rw\nDefaultValue=0\nParameterValue=100\n";
    const auto imported = import_eds(dcf, "node.dcf");
    ASSERT_TRUE(imported.ok()) << imported.error();
    EXPECT_EQ(imported->dictionary.get_as<std::uint16_t>(0x1017, 0), 100);
    EXPECT_EQ(imported->dictionary.find(0x1017, 0)->default_value, encode<std::uint16_t>(0));
}

// One VAR object 0x2000 of `type` whose DefaultValue is `text`.
std::string single_value_eds(DataType type, std::string_view text) {
    return fmt::format("[ManufacturerObjects]\nSupportedObjects=1\n1=0x2000\n\n[2000]\n"
                       "ParameterName=Value\nObjectType=0x7\nDataType=0x{:04X}\nAccessType=rw\n"
                       "DefaultValue={}\n",
                       static_cast<std::uint16_t>(type), text);
}

struct ValueCase {
    DataType type;
    const char* text;
    Bytes expected;
};

class EdsValue : public testing::TestWithParam<ValueCase> {};

TEST_P(EdsValue, ReadsEveryNotationCia306Allows) {
    const ValueCase& c = GetParam();
    const auto imported = import_eds(single_value_eds(c.type, c.text), "value.eds", NodeId{5});
    ASSERT_TRUE(imported.ok()) << imported.error();
    EXPECT_EQ(imported->dictionary.get(0x2000, 0), c.expected)
        << to_string(c.type) << " " << c.text;
}

INSTANTIATE_TEST_SUITE_P(
    Table, EdsValue,
    testing::Values(
        ValueCase{DataType::Unsigned8, "255", {0xFF}},
        ValueCase{DataType::Unsigned8, "0xff", {0xFF}},
        ValueCase{DataType::Unsigned8, "0377", {0xFF}}, ValueCase{DataType::Unsigned8, "0", {0x00}},
        ValueCase{DataType::Unsigned8, "", {0x00}},
        ValueCase{DataType::Unsigned16, "$NODEID+0x180", {0x85, 0x01}},
        ValueCase{DataType::Unsigned16, "0x180 + $nodeid", {0x85, 0x01}},
        ValueCase{DataType::Unsigned32, "0x80000000+$NODEID", {0x05, 0x00, 0x00, 0x80}},
        ValueCase{DataType::Integer8, "-128", {0x80}},
        ValueCase{DataType::Integer8, "0x80", {0x80}},
        ValueCase{DataType::Integer16, "-2", {0xFE, 0xFF}},
        ValueCase{DataType::Integer16, "+7", {0x07, 0x00}},
        ValueCase{DataType::Integer24, "-1", {0xFF, 0xFF, 0xFF}},
        ValueCase{DataType::Integer64, "-9223372036854775808", encode(INT64_MIN)},
        ValueCase{DataType::Unsigned64, "18446744073709551615", encode(UINT64_MAX)},
        ValueCase{DataType::Unsigned48, "0xFFFFFFFFFFFF", Bytes(6, 0xFF)},
        ValueCase{DataType::Boolean, "1", {0x01}}, ValueCase{DataType::Boolean, "TRUE", {0x01}},
        ValueCase{DataType::Boolean, "false", {0x00}},
        ValueCase{DataType::Real32, "1.5", encode(1.5F)},
        ValueCase{DataType::Real32, "-2.5e-3", encode(-2.5e-3F)},
        ValueCase{DataType::Real32, "0x3F800000", encode(1.0F)},
        ValueCase{DataType::Real64, "0.1", encode(0.1)},
        ValueCase{DataType::VisibleString, "EPOS2 24/5", encode_string("EPOS2 24/5")},
        ValueCase{DataType::VisibleString, "a=b;c", encode_string("a=b;c")},
        ValueCase{DataType::OctetString, "01 AB ff", Bytes{0x01, 0xAB, 0xFF}},
        ValueCase{DataType::Domain, "DEAD", Bytes{0xDE, 0xAD}},
        ValueCase{DataType::Domain, "", Bytes{}},
        ValueCase{DataType::TimeDifference, "0x010203040506", Bytes{6, 5, 4, 3, 2, 1}}));

// Malformed files: an error that names the file and line, never an exception.
struct MalformedCase {
    const char* what;
    std::string text;
    std::string expected; ///< part of the message, starting with "file:line:"
};

class EdsMalformed : public testing::TestWithParam<MalformedCase> {};

TEST_P(EdsMalformed, IsAnErrorNamingTheLine) {
    const auto imported = import_eds(GetParam().text, "bad.eds");
    ASSERT_FALSE(imported.ok()) << GetParam().what;
    EXPECT_NE(imported.error().find(GetParam().expected), std::string::npos)
        << GetParam().what << ": " << imported.error();
}

std::string manufacturer_object(std::string_view keys) {
    return fmt::format(
        "[ManufacturerObjects]\nSupportedObjects=1\n1=0x2000\n[2000]\nParameterName=V\n{}", keys);
}

const std::vector<MalformedCase> kMalformed = {
    {"key before any section", "Key=1\n", "bad.eds:1: error: key=value before any [section]"},
    {"unterminated section", "\n[FileInfo\n", "bad.eds:2: error: section header without ']'"},
    {"empty section name", "[ ]\n", "bad.eds:1: error: section without a name"},
    {"line without equals", "[FileInfo]\nFileName\n", "bad.eds:2: error: 'FileName' is neither"},
    {"empty key", "[FileInfo]\n=1\n", "bad.eds:2: error: key=value without a key"},
    {"repeated section", "[FileInfo]\n[fileinfo]\n",
     "bad.eds:2: error: section [fileinfo] "
     "repeats the one of line 1"},
    {"repeated key", "[FileInfo]\nFileName=a\nfilename=b\n",
     "bad.eds:3: error: filename repeats the one of line 2 in [FileInfo]"},
    {"control character", "[FileInfo]\nFileName=a\x01\n", "bad.eds:2: error: control character"},
    {"bad number in device info", "[DeviceInfo]\nVendorNumber=0xFG\n",
     "bad.eds:2: error: VendorNumber=0xFG is not a number"},
    {"vendor number too large", "[DeviceInfo]\nVendorNumber=0x100000000\n", "bad.eds:2: error:"},
    {"list longer than its entries", "[OptionalObjects]\nSupportedObjects=2\n1=0x1017\n",
     "bad.eds:2: error: [OptionalObjects] lists 2 objects but has no entry 2"},
    {"listed object without section", "[OptionalObjects]\nSupportedObjects=1\n1=0x1017\n",
     "bad.eds:3: error: object 1017 is listed but has no [1017] section"},
    {"object index zero", "[OptionalObjects]\nSupportedObjects=1\n1=0\n",
     "bad.eds:3: error: '0' is not an object index"},
    {"object listed twice",
     "[MandatoryObjects]\nSupportedObjects=1\n1=0x1000\n[OptionalObjects]\nSupportedObjects=1\n"
     "1=0x1000\n",
     "bad.eds:6: error: object 1000 is listed again (line 3)"},
    {"huge SupportedObjects", "[OptionalObjects]\nSupportedObjects=99999999\n",
     "bad.eds:2: error: SupportedObjects=99999999 is not a number from 0 to 65536"},
    {"no parameter name", "[ManufacturerObjects]\nSupportedObjects=1\n1=0x2000\n[2000]\n",
     "bad.eds:4: error: [2000] has no ParameterName"},
    {"no data type", manufacturer_object("AccessType=rw\n"),
     "bad.eds:4: error: [2000] needs DataType and AccessType"},
    {"unknown data type", manufacturer_object("DataType=0x0020\nAccessType=rw\n"),
     "bad.eds:6: error: DataType=0x0020 is not a static data type"},
    {"unknown access", manufacturer_object("DataType=0x0005\nAccessType=readwrite\n"),
     "bad.eds:7: error: AccessType=readwrite is none of"},
    {"unknown object type", manufacturer_object("ObjectType=0x3\n"),
     "bad.eds:6: error: ObjectType=0x3 is none of"},
    {"default too large", manufacturer_object("DataType=5\nAccessType=rw\nDefaultValue=256\n"),
     "bad.eds:8: error: DefaultValue: '256' does not fit UNSIGNED8"},
    {"negative unsigned", manufacturer_object("DataType=6\nAccessType=rw\nDefaultValue=-1\n"),
     "bad.eds:8: error: DefaultValue: '-1' does not fit UNSIGNED16"},
    {"signed out of range", manufacturer_object("DataType=2\nAccessType=rw\nDefaultValue=128\n"),
     "bad.eds:8: error: DefaultValue: '128' does not fit INTEGER8"},
    {"not a number", manufacturer_object("DataType=7\nAccessType=rw\nDefaultValue=abc\n"),
     "bad.eds:8: error: DefaultValue: 'abc' is not a number"},
    {"node-id without a node-id",
     manufacturer_object("DataType=7\nAccessType=rw\nDefaultValue=$NODEID+0x180\n"),
     "bad.eds:8: error: DefaultValue: $NODEID needs a node-ID"},
    {"negative term in a sum",
     manufacturer_object("DataType=4\nAccessType=rw\nDefaultValue=-1+0x180\n"),
     "bad.eds:8: error: DefaultValue: '-1+0x180': a sum takes no negative terms"},
    {"bad real", manufacturer_object("DataType=8\nAccessType=rw\nDefaultValue=1.5x\n"),
     "bad.eds:8: error: DefaultValue: '1.5x' is not a REAL32"},
    {"odd hex digits", manufacturer_object("DataType=0xA\nAccessType=rw\nDefaultValue=ABC\n"),
     "bad.eds:8: error: DefaultValue: 'ABC' is not a OCTET_STRING in hex byte pairs"},
    {"limits crossed",
     manufacturer_object("DataType=3\nAccessType=rw\nLowLimit=10\nHighLimit=-10\n"),
     "bad.eds:9: error: HighLimit is below LowLimit"},
    {"limit on a string", manufacturer_object("DataType=9\nAccessType=rw\nLowLimit=1\n"),
     "bad.eds:8: error: LowLimit on a VISIBLE_STRING"},
    {"pdo mapping not a flag", manufacturer_object("DataType=5\nAccessType=rw\nPDOMapping=2\n"),
     "bad.eds:8: error: PDOMapping=2 is not a number from 0 to 1"},
    {"sub number mismatch",
     manufacturer_object("ObjectType=0x9\nSubNumber=2\n[2000sub0]\nParameterName=N\n"
                         "DataType=5\nAccessType=ro\n"),
     "bad.eds:7: error: SubNumber=2 but [2000] has 1 sub-index sections"},
    {"sub-index too large", manufacturer_object("ObjectType=0x9\n[2000sub100]\n"),
     "bad.eds:7: error: [2000sub100]: the sub-index is not 0 to FF in hex"},
    {"sub-index repeated",
     manufacturer_object("ObjectType=0x9\n[2000sub1]\nParameterName=A\n[2000sub01]\n"),
     "bad.eds:9: error: [2000sub01] repeats [2000sub1] of line 7"},
    {"sub without name", manufacturer_object("ObjectType=0x8\n[2000sub1]\nDataType=5\n"),
     "bad.eds:7: error: [2000sub1] has no ParameterName"},
    {"compact on a VAR",
     manufacturer_object("ObjectType=0x7\nDataType=5\nAccessType=ro\nCompactSubObj=2\n"),
     "bad.eds:9: error: CompactSubObj is for ARRAY objects"},
    {"compact too many", manufacturer_object("ObjectType=0x8\nCompactSubObj=255\n"),
     "bad.eds:7: error: CompactSubObj=255 is not a number from 0 to 254"},
    {"compact value not of the type",
     manufacturer_object("ObjectType=0x8\nDataType=5\nAccessType=ro\nCompactSubObj=1\n"
                         "[2000Value]\nNrOfEntries=1\n1=300\n"),
     "bad.eds:12: error: 1: '300' does not fit UNSIGNED8"},
};

INSTANTIATE_TEST_SUITE_P(Table, EdsMalformed, testing::ValuesIn(kMalformed),
                         [](const auto& param_info) {
                             std::string name;
                             for (const char c : std::string_view(param_info.param.what)) {
                                 name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                             }
                             return name;
                         });

TEST(Eds, ImportSurvivesDamagedFiles) {
    // Deterministic damage of a real-looking file: no input may throw or crash; each either
    // imports or names the file in its error. (The libFuzzer target explores further.)
    std::mt19937 random(20240115);
    const std::string original(kVendorEds);
    for (int round = 0; round < 1500; ++round) {
        std::string text = original;
        const int edits = 1 + static_cast<int>(random() % 4);
        for (int e = 0; e < edits; ++e) {
            const std::size_t at = random() % (text.size() + 1);
            switch (random() % 4) {
            case 0:
                text.insert(at, 1, "=[]$+;x0\n\r"[random() % 10]);
                break;
            case 1:
                text.erase(at, random() % 16);
                break;
            case 2:
                if (at < text.size()) {
                    text[at] = static_cast<char>(random() % 256);
                }
                break;
            default:
                text.resize(at);
                break;
            }
        }
        const auto imported = import_eds(text, "damaged.eds", NodeId{1});
        if (!imported.ok()) {
            EXPECT_EQ(imported.error().rfind("damaged.eds:", 0), 0U) << imported.error();
        }
    }
}

} // namespace
} // namespace eposp::canopen

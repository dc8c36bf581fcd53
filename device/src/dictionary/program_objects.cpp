// CiA 302-3 program download, as the EPOS P's service tools use it (docs/service-interface.md,
// "Program download and program control"): 0x1F50, 0x1F51, 0x1F56, 0x1F57, each an ARRAY with
// sub-index 1 for the one program the EPOS P holds. Their behaviour is program_download.cpp's.
#include "eposp/canopen/entry_builder.hpp"
#include "object_areas.hpp"

namespace eposp::device::dictionary {

using namespace canopen::od_types;

void add_program_objects(canopen::ObjectDictionary& od) {
    od.add_object(kProgramDataIndex, "Program Data", kArray);
    // The image's bytes; the dictionary's limit on DOMAINs (1 MiB) bounds a download.
    od.add_sub(kProgramDataIndex, 1, "Program Number 1", canopen::DataType::Domain, kRW, {});
    od.add_object(kCia302ProgramControlIndex, "Program Control", kArray);
    add_entry(od, kCia302ProgramControlIndex, 1, "Program Number 1", kU8, kRW,
              static_cast<std::int64_t>(ProgramControlCommand::Clear)) // no program
        .one_of({0, 1, 2, 3});
    od.add_object(kProgramIdentificationIndex, "Program Software Identification", kArray);
    add_entry(od, kProgramIdentificationIndex, 1, "Program Number 1", kU32, kRO, 0);
    od.add_object(kFlashStatusIndex, "Flash Status Identification", kArray);
    add_entry(od, kFlashStatusIndex, 1, "Program Number 1", kU32, kRO, 1 << 1); // no valid program
}

} // namespace eposp::device::dictionary

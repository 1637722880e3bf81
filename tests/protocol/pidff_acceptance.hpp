// A model of what Linux's hid-pidff (drivers/hid/usbhid/hid-pidff.c, Linux 6.1) checks
// when it initialises force feedback on a HID device, applied to a parsed descriptor.
//
// Written from a reading of hid-pidff.c and hid-core.c (not from feel's descriptor code),
// so that a descriptor change that the kernel would refuse fails a unit test before the
// Linux VM rig (tests/linux/) even boots. What the kernel does, step by step:
//
//  1. hid-core gives every field the usage of the innermost Logical collection around it
//     (field->logical). hid-pidff walks the output reports, then the feature reports, and
//     files a report under a PID report usage when its FIRST field's logical usage is one
//     of Set Effect 0x21, Effect Operation 0x77, Device Gain 0x7D, PID Pool 0x7F, Block
//     Load 0x89, Block Free 0x90, Device Control 0x96 (not 0x95: the usage of the list that
//     is that report's only field in the standard layout), Create New Effect 0xAB, Set
//     Envelope 0x5A, Set Condition 0x5F, Set Periodic 0x6E, Set Constant 0x73, Set Ramp
//     0x74. The first eight are required.
//  2. It looks up value usages per report ("pidff_find_fields"), considering only fields
//     whose usage count equals their Report Count (hid-core's maxusage == report_count;
//     Array fields with a usage list are skipped): Set Effect needs Effect Block Index
//     0x22, Duration 0x50, Gain 0x52, Trigger Button 0x53, Trigger Repeat Interval 0x54,
//     Direction Enable 0x56 and Start Delay 0xA7; Block Load 0x22 (and reads RAM Pool
//     Available 0xAC); Effect Operation 0x22 and Loop Count 0x7C; Block Free 0x22; Set
//     Envelope 0x22 0x5B 0x5C 0x5D 0x5E (else constant, ramp and periodic are dropped); Set
//     Constant 0x22 0x70; Set Ramp 0x22 0x75 0x76; Set Condition 0x22 0x23 0x60..0x65; Set
//     Periodic 0x22 0x70 0x6F 0x71 0x72; Device Gain 0x7E (else no FF_GAIN); PID Pool
//     0x80 0x83 0xA9 (optional).
//  3. "Special fields": the first field whose logical usage is Effect Type 0x25 (in Create
//     New Effect and in Set Effect), Direction 0x57 (Set Effect), Device Control 0x96,
//     Block Load Status 0x8B and Effect Operation 0x78; all but Direction must have
//     Logical Minimum 1 ("logical_minimum is not 1 as it should be"). Their usage lists
//     must hold Block Load Success 0x8C and Full 0x8D, Op Effect Start 0x79 and Stop 0x7B,
//     and at least one of the eleven ET usages it knows.
//  4. For each known effect type at list position j it compares usage[j + 1] of the two
//     Effect Type lists (its index is 1-based and it indexes the 0-based usage array with
//     it): the lists must agree there, and j + 1 must stay inside the list.
//  5. PID Pool's Device Managed Pool, when present, must read 1 (else -EPERM); the number
//     of effects is Block Load index's Logical Maximum - Minimum + 1 (at most 64), and
//     autocenter is offered only when the first block the device hands out is Logical
//     Minimum + 1.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "feel/protocol/descriptor_parser.hpp"

namespace feel::protocol::test {

struct PidffVerdict {
    std::vector<std::string> problems;  // empty: hid-pidff initialises
    int max_effects = 0;                // what input_ff_create gets
    int64_t first_block = 0;            // Block Load index's Logical Minimum
    std::vector<uint16_t> ff_effects;   // PID ET usages it maps to FF_* bits
    bool gain = false;                  // FF_GAIN
    [[nodiscard]] bool accepted() const noexcept { return problems.empty(); }
};

[[nodiscard]] PidffVerdict pidff_check(const hid::ParsedDescriptor& descriptor);

}  // namespace feel::protocol::test

// powerkey: the umbrella header. Includes every public header and nothing else.
#ifndef POWERKEY_POWERKEY_HPP
#define POWERKEY_POWERKEY_HPP

#include <powerkey/bounded.hpp>
#include <powerkey/describe.hpp>
#include <powerkey/enum_names.hpp>
#include <powerkey/error.hpp>
#include <powerkey/fields.hpp>
#include <powerkey/frame_form.hpp>
#include <powerkey/index_set.hpp>
#include <powerkey/names.hpp>
#include <powerkey/result.hpp>
#include <powerkey/session.hpp>
#include <powerkey/version.hpp>

#include <powerkey/behaviour/checker.hpp>
#include <powerkey/behaviour/clock.hpp>
#include <powerkey/behaviour/controller.hpp>
#include <powerkey/behaviour/j1939_checks.hpp>
#include <powerkey/behaviour/j1939_controller.hpp>
#include <powerkey/behaviour/j1939_keypad.hpp>
#include <powerkey/behaviour/key_modes.hpp>
#include <powerkey/behaviour/key_timing.hpp>
#include <powerkey/behaviour/virtual_keypad.hpp>

#include <powerkey/can/candump.hpp>
#include <powerkey/can/frame.hpp>

#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/canopen/heartbeat.hpp>
#include <powerkey/canopen/nmt.hpp>
#include <powerkey/canopen/node_id.hpp>
#include <powerkey/canopen/sdo.hpp>
#include <powerkey/canopen/sdo_upload.hpp>
#include <powerkey/canopen/sync.hpp>

#include <powerkey/j1939/id.hpp>
#include <powerkey/j1939/name.hpp>
#include <powerkey/j1939/protocol_switch.hpp>
#include <powerkey/keypad/j1939_codec.hpp>
#include <powerkey/keypad/j1939_messages.hpp>
#include <powerkey/keypad/j1939_models.hpp>

#include <powerkey/keypad/accessors.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/keypad/commands.hpp>
#include <powerkey/keypad/dictionaries.hpp>
#include <powerkey/keypad/lookup.hpp>
#include <powerkey/keypad/messages.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/keypad/objects.hpp>
#include <powerkey/keypad/value_kinds.hpp>
#include <powerkey/keypad/values.hpp>

#endif  // POWERKEY_POWERKEY_HPP

// powerkey: the umbrella header. Includes every public header and nothing else.
#ifndef POWERKEY_POWERKEY_HPP
#define POWERKEY_POWERKEY_HPP

#include <powerkey/bounded.hpp>
#include <powerkey/decoder.hpp>
#include <powerkey/describe.hpp>
#include <powerkey/error.hpp>
#include <powerkey/fields.hpp>
#include <powerkey/index_set.hpp>
#include <powerkey/result.hpp>
#include <powerkey/session.hpp>
#include <powerkey/version.hpp>

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
#include <powerkey/j1939/protocol_switch.hpp>

#include <powerkey/pk1000/objects.hpp>
#include <powerkey/pk1000/pdo.hpp>
#include <powerkey/pk1000/profile.hpp>
#include <powerkey/pk1000/values.hpp>

#include <powerkey/pkp/command.hpp>
#include <powerkey/pkp/model.hpp>
#include <powerkey/pkp/objects.hpp>
#include <powerkey/pkp/pdo.hpp>
#include <powerkey/pkp/profile.hpp>

// The any-frame decoder, the session follower and the description writer, over every model.
#include <powerkey/decoder.hpp>
#include <powerkey/describe.hpp>
#include <powerkey/fields.hpp>
#include <powerkey/session.hpp>

#endif  // POWERKEY_POWERKEY_HPP

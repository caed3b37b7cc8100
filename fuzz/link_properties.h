// Properties of linked portals (teleports, mirrors) on hand-built worlds with non-identity cell
// frames: termination within the bound, determinism, and conservativeness against a ray walk that
// follows the links. Part of visibility_properties (rapidcheck); returns whether they held.
#pragma once

namespace lintel::fuzz {

bool check_linked_portals();

}  // namespace lintel::fuzz

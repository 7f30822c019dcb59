// SPDX-License-Identifier: MIT
// The store's schema as an ordered list of migrations: migration N brings a store from version
// N-1 to N. A new store runs them all; an older one the ones it lacks; a newer one is refused.
#pragma once

#include <soci/soci.h>

#include <string>

#include "store_migration.h"
#include "store_url.h"

namespace flange::host {

// The schema version of the store behind `sql`: 0 when it holds no tables at all. Throws
// StoreError when it holds tables but is not a flange store.
int stored_schema_version(soci::session& sql, const StoreUrl& url);

// Creates or migrates the store to `target` in one transaction (serialised against other
// processes doing the same). Throws StoreError for a store newer than `target`.
void migrate_store(soci::session& sql, const StoreUrl& url, int target = kStoreSchemaVersion);

}  // namespace flange::host

/* SPDX-License-Identifier: GPL-2.0-or-later */
/* One closure library built several ways (see CMakeLists.txt). */
#include "broken_common.h"

#if defined(TOY_TWO_WITH_ONE_NAME)
static const sl_closure_desc *const all[] = {&toy, &toy};
#else
static const sl_closure_desc *const all[] = {&toy};
#endif

#if defined(TOY_NO_ENTRY)
SL_EXPORT const sl_closure_desc *const *toy_entry(int32_t *count);
SL_EXPORT const sl_closure_desc *const *toy_entry(int32_t *count) {
#elif defined(TOY_ENTRY_V2)
SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v2(int32_t *count);
SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v2(int32_t *count) {
#else
SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
#endif
  *count = SL_COUNT_OF(all);
  return all;
}

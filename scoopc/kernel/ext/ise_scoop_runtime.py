"""ISE_SCOOP_RUNTIME's `external "Python"` feature (stdlib/base/kernel/ise_scoop_runtime.e)."""


def region_id(current, a_object):
    """The identifier of `a_object`'s region: the runtime's processor id less one, so the root
    region is 0 as in EiffelStudio, wrapped to NATURAL_16 short of `invalid_region_id`
    (0xFFFF). A value without a region (an expanded value) is in the caller's region."""
    region = getattr(a_object, "_region_", None)
    if region is None:
        region = current._region_
    return (region.id - 1) % 0xFFFF

"""Layer 2, materials: the properties of the bodies in contact (E*, Dundurs beta, w12, C_NS), each defined once."""

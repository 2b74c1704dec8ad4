"""ArtiMo: text-driven articulated mesh animation."""

"""Layer 5, the main job (``memstribo run``): its stages, figures and report.html."""

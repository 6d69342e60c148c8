"""How the run's heavy stages use the machine (issue 40 item 4): a local Dask cluster of its cores where the stage
has enough cycles to share, and the run's settings of the decision analysis."""

from __future__ import annotations

import logging

__all__ = ["PARALLEL_SAMPLES", "ENSEMBLE_REALISATIONS", "RUN_DECISION", "RUN_CRITICAL", "RUN_SOLVE_SETS", "machine_cores", "stage_cluster", "StageWorkers",
           "ensemble_point_and_cycle", "coated_cycle"]

#: the uncertainty stage runs its cycles on a local Dask cluster of the machine's cores from this many samples on
#: (fewer: the cluster's start-up, a few seconds, would cost more than it saves; issue 40 item 4)
PARALLEL_SAMPLES = 32

#: the mesh stage's roughness realisations run on the cluster from this many on (issue 40 item 4)
ENSEMBLE_REALISATIONS = 8

#: the run's decision analysis (MODEL 7h): the regional index on the stage's own samples only (issue 40: the end
#: points, critical values and robust-Bayes bands of the constants that need contact solves were ~500 of the stage's
#: ~570 cycles); ``memstribo mesh --uncertainty 64 --sobol`` runs them all ("full")
RUN_DECISION = {"depth": "regional"}

#: the run's samples: two constant sets share the values of the constants that need a contact solve (2 solves per
#: realisation of its 4 sets), the rescaled bond energies keep all 4: half the solves; the interval is Wilson's at
#: the design effect's samples (``solve_sets`` of :func:`memstribo.uncertainty.study.uncertainty_study`; the same
#: default as ``memstribo mesh --uncertainty``)
RUN_SOLVE_SETS = "pairs"

#: the run's critical values: those of the rescaled bond energies (no new cycle); the others: ``mesh --uncertainty``
RUN_CRITICAL = "rescaled"


def machine_cores() -> int:
    """The cores this process may run on (its CPU affinity where the system has one): the rule the cycle's row
    threads use (:mod:`memstribo.simulations.mesh.threads`), one place for both."""
    from memstribo.simulations.mesh.threads import _cores

    return _cores()


def stage_cluster(samples, stage: str, threshold: int = PARALLEL_SAMPLES):
    """A local Dask cluster of this machine's cores (one thread each; Dask's workers start with OMP, MKL and
    OpenBLAS at one thread) for a stage of ``samples`` cycles, or None: one core, too few samples, or no
    dask.distributed. Logged, so the run says how it ran."""
    log = logging.getLogger("memstribo.run")
    cores = machine_cores()
    if cores < 2 or samples < threshold:
        log.info("%s: the cycles run in this process (%s)", stage,
                 "one core" if cores < 2 else f"{samples} cycles, under {threshold}")
        return None
    try:
        from memstribo.simulations.study import local_cluster

        cluster = local_cluster(cores)
    except ImportError:
        log.info("%s: the cycles run in this process (dask.distributed is not installed)", stage)
        return None
    log.info("%s: the cycles run on %d worker processes (this machine's cores), one thread each", stage, cores)
    return cluster


class StageWorkers:
    """One local cluster for the run's stages, started by the first stage that has work for it
    (:func:`stage_cluster`) and kept for the next; :meth:`close` at the end of the run."""

    def __init__(self):
        self.cluster = self._client = None

    def client(self, count: int, stage: str, threshold: int = PARALLEL_SAMPLES):
        """A Dask client of the run's cluster for ``count`` cycles of ``stage``, or None (run them in this process)."""
        if self._client is not None:
            logging.getLogger("memstribo.run").info("%s: the cycles run on the run's %d worker processes", stage,
                                                    len(self._client.scheduler_info().get("workers", {})))
            return self._client
        self.cluster = stage_cluster(count, stage, threshold)
        if self.cluster is not None:
            from distributed import Client

            self._client = Client(self.cluster, set_as_default=False)
        return self._client

    def existing(self, stage: str):
        """The run's cluster's client where an earlier stage started it, else None (a few cycles do not start one)."""
        if self._client is not None:
            logging.getLogger("memstribo.run").info("%s: the cycles run on the run's %d worker processes", stage,
                                                    len(self._client.scheduler_info().get("workers", {})))
        return self._client

    def close(self) -> None:
        if self._client is not None:
            self._client.close()
            self.cluster.close()
        self.cluster = self._client = None


def ensemble_point_and_cycle(params, roughness, steps, coating, wear, realisation):
    """(summary, reduced cycle) of one realisation of the run's mesh ensemble: the uncertainty stage takes the cycle
    as its nominal realisation instead of solving it again (issue 40; the same function of the same inputs)."""
    from memstribo.simulations.mesh import simulate_mesh, summarize
    from memstribo.uncertainty.rescale import reduce_cycle

    dataset = simulate_mesh(params, roughness, steps=steps, coating=coating, wear=wear, realisation=realisation)
    summary = summarize(dataset)
    summary.update(realisation=realisation, seed=[int(params["roughness_seed"]), int(realisation)])
    return summary, reduce_cycle(dataset)


def coated_cycle(params, coating_name, roughness, steps, wear):
    """One cycle of the run's wear sweep (the coating by name, worn fraction ``wear``), as
    :func:`memstribo.simulations.coating_wear.wear_sweep` computes it: run on the run's cluster (issue 40)."""
    from memstribo.physics.coating import get_coating
    from memstribo.simulations.mesh import simulate_mesh

    return simulate_mesh(params, roughness, steps=steps, coating=get_coating(coating_name, params), wear=float(wear))

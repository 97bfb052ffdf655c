// How ranks talk: on one machine Open MPI's shared-memory path, without probing fabrics first.
#pragma once

namespace compliant
{
  // Call before MPI_Init. Open MPI 4.1 picks its point-to-point layer by opening every fabric
  // it was built with; Debian's includes PSM (InfiniPath), whose library spends 0.2 s timing
  // the processor in MPI_Init on every start, with or without the hardware. When all ranks run
  // on this one node (a singleton, or mpirun's local size equal to its world size) no fabric is
  // used, so this asks for the ob1 layer (shared memory between ranks) and the probe is skipped.
  // A process started without mpirun also runs without Open MPI's daemon (it spawns nothing);
  // under mpirun the PMIx client takes its job data by message, not from a shared-memory store.
  // A user's own OMPI_MCA_pml wins; runs across nodes are left to Open MPI; other MPIs are not
  // touched. Every rank sees the same environment, so all ranks choose alike.
  // Returns true where it set the layer.
  bool prefer_shared_memory_transport();
} // namespace compliant

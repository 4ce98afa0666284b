using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// Sees every call that changes the engine or asks it a move or a cast, with its answer, in the order the calls are made:
/// set one as <see cref="PhysicsEngine.Recorder"/> to capture a run, and replay the calls in that order on a fresh engine
/// holding the same landblocks to get every answer again, bit for bit (the engine's answers are the same bits in every
/// process).
/// </summary>
/// <remarks>
/// <para>
/// Seen: <see cref="PhysicsEngine.AddLandblock(uint, TerrainSurface, IReadOnlyList{CellSurface}, IReadOnlyList{ObjectSurface})"/>
/// (and the three-argument call) and <see cref="PhysicsEngine.RemoveLandblock"/> by the landblock's id only (the surfaces
/// are the caller's: a replay builds them again from what built them); the mover registry's <see cref="MoverRegistry.Add"/>,
/// <see cref="MoverRegistry.Move"/>, <see cref="MoverRegistry.SetState"/>, <see cref="MoverRegistry.Open"/>,
/// <see cref="MoverRegistry.Close"/>, <see cref="MoverRegistry.Remove"/>, <see cref="MoverRegistry.RemoveLandblock"/> and
/// <see cref="MoverRegistry.Commit"/>; the general move <see cref="PhysicsEngine.Resolve(in MoveRequest, Span{uint})"/> and
/// <see cref="PhysicsEngine.Cast(in CastRequest)"/>. Not seen: the spec's four-argument <c>Resolve</c> and the call with
/// <see cref="MovementOptions"/> (the engine's fastest calls stay as they are), and the queries that neither change the engine
/// nor answer a move (the ground, <see cref="PhysicsEngine.FindCell"/>, door states).
/// </para>
/// <para>
/// A call that throws is not seen: it changed nothing. Each method is called on the thread that made the call, after the
/// call has done its work and before it returns; the registry's calls are seen inside its lock, so they are seen in the
/// order they took effect. Moves and casts made on several threads at once are seen concurrently: a recorder that takes
/// them from several threads must be safe for that, and a capture of them replays exactly only where the calls' order did
/// not matter. Positions are world metres in the engine's frame (<see cref="PhysicsEngine(uint)"/>).
/// </para>
/// <para>
/// A recorder should not throw: an exception it throws reaches the caller after the call has taken effect (the registry's
/// lock released on the way out). It should return quickly, as the caller waits for it, and keep nothing it is handed
/// but copies (the span is the caller's).
/// </para>
/// </remarks>
public interface IEngineRecorder
{
    /// <summary>A landblock was registered (or replaced): <c>0xXXYYFFFF</c>, the low 16 bits set.</summary>
    /// <param name="landblockId">Its id, <c>0xXXYYFFFF</c>.</param>
    void LandblockAdded(uint landblockId);

    /// <summary>A landblock was removed (or was not registered: the call did nothing).</summary>
    /// <param name="landblockId">The id as the caller gave it (any low 16 bits).</param>
    void LandblockRemoved(uint landblockId);

    /// <summary>A mover was registered (<see cref="MoverRegistry.Add"/>), with the arguments of that call.</summary>
    /// <param name="id">Its id.</param>
    /// <param name="shape">Its walls, the caller's instance (describe it by what built it: <see cref="MoverShape.CylinderBody"/> for a cylinder).</param>
    /// <param name="position">Its origin, world metres.</param>
    /// <param name="cellId">Its cell, <c>0xXXYYCCCC</c>.</param>
    /// <param name="orientation">Its turn about Z, as given.</param>
    /// <param name="state">Its state.</param>
    void MoverAdded(uint id, MoverShape shape, Vector3 position, uint cellId, Quaternion orientation, MoverState state);

    /// <summary>A mover was moved (<see cref="MoverRegistry.Move"/>), with the arguments of that call.</summary>
    /// <param name="id">Its id.</param>
    /// <param name="position">Its origin, world metres.</param>
    /// <param name="cellId">Its cell, <c>0xXXYYCCCC</c>.</param>
    /// <param name="orientation">Its turn about Z, as given.</param>
    void MoverMoved(uint id, Vector3 position, uint cellId, Quaternion orientation);

    /// <summary>A mover's state was set (<see cref="MoverRegistry.SetState"/>).</summary>
    /// <param name="id">Its id.</param>
    /// <param name="state">The state set.</param>
    void MoverStateSet(uint id, MoverState state);

    /// <summary>A door was opened (<see cref="MoverRegistry.Open"/>).</summary>
    /// <param name="doorId">Its id.</param>
    void DoorOpened(uint doorId);

    /// <summary>A door was told to close (<see cref="MoverRegistry.Close"/>).</summary>
    /// <param name="doorId">Its id.</param>
    void DoorClosed(uint doorId);

    /// <summary>A mover was removed (<see cref="MoverRegistry.Remove"/>), with the call's answer.</summary>
    /// <param name="id">The id as given.</param>
    /// <param name="removed">Whether it was registered (the call's answer).</param>
    void MoverRemoved(uint id, bool removed);

    /// <summary>The movers of a landblock were removed (<see cref="MoverRegistry.RemoveLandblock"/>), with the call's answer.</summary>
    /// <param name="landblockId">The id as given.</param>
    /// <param name="removed">How many were removed (the call's answer).</param>
    void MoversOfLandblockRemoved(uint landblockId, int removed);

    /// <summary>The movers' changes were published (<see cref="MoverRegistry.Commit"/>).</summary>
    /// <param name="commitNumber">The commit's number (<see cref="MoverRegistry.CommitNumber"/> after it).</param>
    void Committed(long commitNumber);

    /// <summary>A move was answered (<see cref="PhysicsEngine.Resolve(in MoveRequest, Span{uint})"/>).</summary>
    /// <param name="request">The request.</param>
    /// <param name="touched">The caller's span as the call left it: its length is the span's the caller gave; its first <c>min(TouchedCount, Length)</c> ids are the call's.</param>
    /// <param name="result">The answer.</param>
    void Resolved(in MoveRequest request, ReadOnlySpan<uint> touched, in MoveResult result);

    /// <summary>A cast was answered (<see cref="PhysicsEngine.Cast(in CastRequest)"/>).</summary>
    /// <param name="request">The request.</param>
    /// <param name="hit">The answer.</param>
    void Cast(in CastRequest request, in CastHit hit);
}

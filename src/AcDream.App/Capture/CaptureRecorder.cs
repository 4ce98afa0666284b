using System.Numerics;
using System.Text.Json;
using AcDream.App.World;
using AcDream.Core.Physics;

namespace AcDream.App.Capture;

/// <summary>
/// Records an engine's calls (<see cref="IEngineRecorder"/>, set as <see cref="PhysicsEngine.Recorder"/>) as a capture's
/// JSON Lines (<see cref="CaptureJson"/>): the header at once, then one line per call as it is made. A mover's shape is
/// named as the scene's world built it: a cylinder by its size, a door's slab by the door's name; a shape it cannot name is
/// written <c>{"door":null}</c>, which a replay refuses at that line.
/// </summary>
internal sealed class CaptureRecorder : IEngineRecorder
{
    private readonly object _gate = new();
    private readonly TextWriter _output;
    private readonly HoltburgWorld _world;

    /// <summary>Writes the header to <paramref name="output"/>; the calls follow, one line each.</summary>
    /// <param name="output">Where the lines go (not closed here).</param>
    /// <param name="header">The scene and the engine's frame.</param>
    /// <param name="world">The scene's world: its doors name the door shapes.</param>
    public CaptureRecorder(TextWriter output, CaptureHeader header, HoltburgWorld world)
    {
        (_output, _world) = (output, world);
        _output.WriteLine(CaptureJson.Text(w => CaptureJson.WriteHeader(w, header)));
    }

    /// <summary>How many calls have been written.</summary>
    public int Calls { get; private set; }

    /// <inheritdoc/>
    public void LandblockAdded(uint landblockId) => Write(new CaptureCall(CaptureKind.AddLandblock) { Id = landblockId });

    /// <inheritdoc/>
    public void LandblockRemoved(uint landblockId) => Write(new CaptureCall(CaptureKind.RemoveLandblock) { Id = landblockId });

    /// <inheritdoc/>
    public void MoverAdded(uint id, MoverShape shape, Vector3 position, uint cellId, Quaternion orientation, MoverState state) =>
        Write(new CaptureCall(CaptureKind.AddMover) { Id = id, Shape = Name(shape), Position = position, CellId = cellId, Orientation = orientation, State = state });

    /// <inheritdoc/>
    public void MoverMoved(uint id, Vector3 position, uint cellId, Quaternion orientation) =>
        Write(new CaptureCall(CaptureKind.MoveMover) { Id = id, Position = position, CellId = cellId, Orientation = orientation });

    /// <inheritdoc/>
    public void MoverStateSet(uint id, MoverState state) => Write(new CaptureCall(CaptureKind.SetState) { Id = id, State = state });

    /// <inheritdoc/>
    public void DoorOpened(uint doorId) => Write(new CaptureCall(CaptureKind.Open) { Id = doorId });

    /// <inheritdoc/>
    public void DoorClosed(uint doorId) => Write(new CaptureCall(CaptureKind.Close) { Id = doorId });

    /// <inheritdoc/>
    public void MoverRemoved(uint id, bool removed) => Write(new CaptureCall(CaptureKind.RemoveMover) { Id = id, Answer = new CaptureAnswer(Removed: removed) });

    /// <inheritdoc/>
    public void MoversOfLandblockRemoved(uint landblockId, int removed) =>
        Write(new CaptureCall(CaptureKind.RemoveMovers) { Id = landblockId, Answer = new CaptureAnswer(Count: removed) });

    /// <inheritdoc/>
    public void Committed(long commitNumber) => Write(new CaptureCall(CaptureKind.Commit) { Answer = new CaptureAnswer(Commit: commitNumber) });

    /// <inheritdoc/>
    public void Resolved(in MoveRequest request, ReadOnlySpan<uint> touched, in MoveResult result) =>
        Write(new CaptureCall(CaptureKind.Resolve)
        {
            Move = request,
            Span = touched.Length,
            Answer = new CaptureAnswer(Move: result, Touched: touched[..Math.Min(result.TouchedCount, touched.Length)].ToArray()),
        });

    /// <inheritdoc/>
    public void Cast(in CastRequest request, in CastHit hit) => Write(new CaptureCall(CaptureKind.Cast) { Cast = request, Answer = new CaptureAnswer(Hit: hit) });

    private CaptureShape Name(MoverShape shape)
    {
        if (shape.CylinderBody is MoverBody body)
        {
            return new CaptureShape(body, null);
        }

        return new CaptureShape(null, _world.Doors.Values.FirstOrDefault(d => ReferenceEquals(d.Shape, shape))?.Name);
    }

    private void Write(CaptureCall call)
    {
        string line = CaptureJson.Text(w => CaptureJson.WriteCall(w, call));
        lock (_gate)
        {
            _output.WriteLine(line);
            Calls++;
        }
    }
}

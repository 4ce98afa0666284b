using System.Numerics;
using AcDream.App.Streaming;
using AcDream.Core.Dat;
using AcDream.Core.Physics;

namespace AcDream.App;

/// <summary>
/// The headless client window: owns the <see cref="PhysicsEngine"/> and what is registered in it,
/// and runs streaming for the frame loop, which calls <see cref="UpdateStreaming"/> once per frame:
/// it drains the loads that finished into the engine, unloads landblocks the observer left behind
/// and requests the ones it approaches. The three jobs behind it have a type each: the
/// <see cref="LandblockStreamer"/> decides which landblocks to load and unload, the
/// <see cref="LandblockLoader"/>'s background thread reads them from an <see cref="ILandblockSource"/>,
/// and <see cref="DatSurfaces"/> turns a landblock's dat data into the engine's surfaces.
/// </summary>
/// <remarks>
/// The streaming window is the square of landblocks within <see cref="StreamingRadius"/> of the
/// observer's landblock (3 × 3), clipped to the world. The engine is touched only by the frame
/// thread; the loader thread only reads from the source. The two share only the request and result
/// queues, under a lock that no callback runs inside. A cell or an object (of the landblock's
/// <see cref="LandBlockInfo"/> or a cell's static objects) that cannot be built is skipped with
/// a warning; a landblock that cannot be built at all is not registered (the engine never holds half
/// of one), is reported, and is requested again <see cref="RetryDelayFrames"/> frames later.
/// The host's movers (creatures, the player, doors: <see cref="AddMover"/>, <see cref="MoveMover"/>) live in loaded
/// landblocks: a landblock that unloads takes the movers whose cell is in it out of the engine with it, and the frame
/// loop publishes the frame's changes to them once per frame (<see cref="CommitMovers"/>).
/// </remarks>
public sealed class GameWindow : IDisposable
{
    /// <summary>Landblocks kept loaded on each side of the observer's: 1, a 3 × 3 square.</summary>
    public const int StreamingRadius = 1;

    /// <summary>Frames (<see cref="UpdateStreaming"/> calls) before a failed landblock is requested again: 30, one second at 30 Hz.</summary>
    public const int RetryDelayFrames = 30;

    private readonly DatSurfaces _surfaces;
    private readonly Action<string> _log;
    private readonly LandblockStreamer _streamer = new();
    private readonly LandblockLoader _loader;

    // Frame thread only: what is registered in the engine.
    private readonly HashSet<uint> _loaded = [];
    private readonly Dictionary<uint, int> _objectCounts = [];

    /// <summary>
    /// Creates the window and starts its loader thread. Nothing is loaded until the first
    /// <see cref="UpdateStreaming"/>.
    /// </summary>
    /// <param name="source">Where landblocks come from; called on the loader thread.</param>
    /// <param name="heightTable">The region's 256 heights in metres (<c>LandHeightTable</c>); copied.</param>
    /// <param name="centerLandblockId">The landblock whose south-west corner is world (0, 0), <c>0xXXYYFFFF</c>.</param>
    /// <param name="log">Receives warnings and load failures, one line each; null to discard them.</param>
    /// <exception cref="ArgumentException">The table does not have 256 finite entries, or the id is not a landblock of the world.</exception>
    public GameWindow(ILandblockSource source, float[] heightTable, uint centerLandblockId, Action<string>? log = null)
    {
        ArgumentNullException.ThrowIfNull(source);
        _log = log ?? (_ => { });
        _surfaces = new DatSurfaces(heightTable, _log);
        Physics = new PhysicsEngine(centerLandblockId);
        _loader = new LandblockLoader(source);
    }

    /// <summary>Raised on the frame thread after a landblock (<c>0xXXYYFFFF</c>) is registered in the engine.</summary>
    public event Action<uint>? LandblockLoaded;

    /// <summary>Raised on the frame thread after a landblock (<c>0xXXYYFFFF</c>) is removed from the engine.</summary>
    public event Action<uint>? LandblockUnloaded;

    /// <summary>The engine, in the world frame of the centre landblock (metres; world (0, 0) is its south-west corner).</summary>
    public PhysicsEngine Physics { get; }

    /// <summary>The landblocks (<c>0xXXYYFFFF</c>) registered in the engine. Frame thread only.</summary>
    public IReadOnlyCollection<uint> LoadedLandblocks => _loaded;

    /// <summary>The landblocks (<c>0xXXYYFFFF</c>) the streaming window wants, as of the last <see cref="UpdateStreaming"/>. Frame thread only.</summary>
    public IReadOnlyCollection<uint> WindowLandblocks => _streamer.Window;

    /// <summary>
    /// The landblock (<c>0xXXYYFFFF</c>) under a world position; positions off the world (however far,
    /// infinities included) clamp to the nearest edge landblock. The engine's
    /// <see cref="PhysicsEngine.LandblockAt"/>.
    /// </summary>
    /// <param name="worldPosition">World metres (Z is ignored).</param>
    /// <exception cref="ArgumentException">X or Y is NaN.</exception>
    public uint LandblockAt(Vector3 worldPosition) => Physics.LandblockAt(worldPosition);

    /// <summary>
    /// The frame loop's streaming step: moves the window to the observer, registers the loads that
    /// finished (those still in the window), unloads landblocks outside the window, drops the queued
    /// requests that left it, and requests the missing ones; the loader takes the queue nearest first
    /// (by distance to the observer's landblock). Never blocks on a load.
    /// </summary>
    /// <remarks>
    /// <see cref="LandblockLoaded"/>, <see cref="LandblockUnloaded"/> and the log run on this thread
    /// outside the loader's lock (only its hand-over queues take it), so they may call <see cref="Dispose"/>. After
    /// <see cref="Dispose"/> this still registers what finished and unloads, but requests nothing.
    /// </remarks>
    /// <param name="observerWorldPosition">The observer (the player), world metres.</param>
    /// <exception cref="ArgumentException">The observer's X or Y is NaN.</exception>
    public void UpdateStreaming(Vector3 observerWorldPosition)
    {
        _streamer.MoveTo(LandblockAt(observerWorldPosition));
        foreach ((uint id, LoadedLandblock? loaded, string? loadError) in _loader.TakeFinished())
        {
            if (!_streamer.Window.Contains(id))
            {
                continue; // the observer moved on while it loaded
            }

            string? error = loadError;
            if (loaded is null || !ApplyLoadedTerrainLocked(id, loaded, out error))
            {
                _streamer.RetryLater(id);
                _log($"landblock 0x{id:X8}: could not load ({error}); retrying in {RetryDelayFrames} frames.");
            }
        }

        foreach (uint id in _streamer.LeftBehind(_loaded))
        {
            UnloadLandblockLocked(id);
        }

        _streamer.Request(_loader, _loaded);
    }

    /// <summary>
    /// Waits until every landblock requested so far has finished loading (or failed); the next
    /// <see cref="UpdateStreaming"/> registers them. The scene runner calls it to keep runs reproducible.
    /// </summary>
    /// <param name="timeout">How long to wait at most.</param>
    /// <returns>True when nothing is in flight any more; false on time-out.</returns>
    public bool WaitForLoads(TimeSpan timeout) => _loader.WaitForLoads(timeout);

    /// <summary>
    /// Stops the loader thread: a load in progress finishes first, queued requests are dropped.
    /// Safe to call more than once, from a <see cref="LandblockLoaded"/> or
    /// <see cref="LandblockUnloaded"/> handler or the log (they run outside the loader's lock), and
    /// from the source on the loader thread (it then does not wait for the loader to end).
    /// </summary>
    public void Dispose() => _loader.Dispose();

    /// <summary>
    /// Registers a loaded landblock: <see cref="DatSurfaces"/> builds its <see cref="TerrainSurface"/>
    /// (the game's triangles, from the landblock id), one <see cref="CellSurface"/> per cell whose
    /// environment and cell struct resolve, and one <see cref="ObjectSurface"/> per object of its
    /// <see cref="LoadedLandblock.Info"/> and of its registered cells' <see cref="EnvCell.StaticObjects"/>
    /// (<see cref="ObjectSurface.FromLandblock"/>, object by object), and this calls
    /// <c>PhysicsEngine.AddLandblock</c> with them. A cell or an object that cannot be built is skipped
    /// with a warning naming it and the reason; an object standing in a skipped cell is skipped with
    /// it. An object the engine refuses (<see cref="ObjectRefusedException"/>, naming it) is dropped
    /// alone and the rest registered; when the objects together are refused, the landblock is
    /// registered without them.
    /// </summary>
    /// <remarks>
    /// The name is the spec's (Phase B.3 hooks the engine into <c>ApplyLoadedTerrainLocked</c>). Here
    /// "locked" means "on the frame thread, which owns the engine's writes": the loader's lock is not
    /// held while it runs, so events and the log may call back into the window.
    /// </remarks>
    /// <returns>False, with the reason, when the landblock itself cannot be registered; the engine is then unchanged.</returns>
    internal bool ApplyLoadedTerrainLocked(uint landblockId, LoadedLandblock loaded, out string? error)
    {
        uint id = CellIds.LandblockOf(landblockId);
        if (_surfaces.Terrain(id, loaded, out error) is not TerrainSurface terrain)
        {
            return false;
        }

        List<CellSurface> cells = _surfaces.Cells(id, loaded);
        List<ObjectSurface> objects = _surfaces.Objects(id, loaded, cells);
        while (true)
        {
            try
            {
                Physics.AddLandblock(id, terrain, cells, objects);
                break;
            }
            catch (ObjectRefusedException e)
            {
                // The engine names the one object it refuses and why: that object is dropped, the rest kept.
                _log($"landblock 0x{id:X8}: object 0x{e.ObjectId:X8} skipped ({e.Rule}): {e.Message}");
                objects.RemoveAt(e.ObjectIndex);
            }
            catch (ArgumentException e) when (objects.Count > 0)
            {
                // Not one object's fault but their combination (more outdoor objects than the engine takes):
                // the landblock is registered without them.
                _log($"landblock 0x{id:X8}: its {objects.Count} objects skipped: {e.Message}");
                objects.Clear();
            }
            catch (ArgumentException e)
            {
                error = e.Message;
                return false;
            }
        }

        _objectCounts[id] = objects.Count;

        if (_loaded.Add(id))
        {
            LandblockLoaded?.Invoke(id);
        }

        return true;
    }

    /// <summary>
    /// Registers a mover in the engine (<see cref="MoverRegistry.Add"/>) in a loaded landblock: the one of
    /// <paramref name="cellId"/>, which unloading removes it with. Seen by <c>Resolve</c> from the next
    /// <see cref="CommitMovers"/>. Frame thread only.
    /// </summary>
    /// <param name="id">Its id, not 0 and not registered.</param>
    /// <param name="shape">Its walls in its own frame (metres, origin at its position).</param>
    /// <param name="position">Its origin (a creature's feet), world metres.</param>
    /// <param name="cellId">The cell it is in, <c>0xXXYYCCCC</c>, of a loaded landblock.</param>
    /// <param name="orientation">A turn about Z.</param>
    /// <param name="state">What it is and its bits (<see cref="MoverState"/>).</param>
    /// <exception cref="InvalidOperationException">The cell's landblock is not loaded.</exception>
    /// <exception cref="ArgumentException">The engine refuses an argument (<see cref="MoverRegistry.Add"/>).</exception>
    public void AddMover(uint id, MoverShape shape, Vector3 position, uint cellId, Quaternion orientation, MoverState state)
    {
        if (!_loaded.Contains(CellIds.LandblockOf(cellId)))
        {
            throw new InvalidOperationException($"mover 0x{id:X8}: its cell 0x{cellId:X8} is in landblock 0x{CellIds.LandblockOf(cellId):X8}, which is not loaded.");
        }

        Physics.Movers.Add(id, shape, position, cellId, orientation, state);
    }

    /// <summary>
    /// Moves a registered mover (<see cref="MoverRegistry.Move"/>: seen from the next <see cref="CommitMovers"/>); allocates
    /// nothing. A move the engine resolved stays in loaded land, so its landblock is loaded. Frame thread only.
    /// </summary>
    /// <param name="id">A registered mover's id.</param>
    /// <param name="position">Its origin, world metres.</param>
    /// <param name="cellId">The cell it is now in, <c>0xXXYYCCCC</c>.</param>
    /// <param name="orientation">A turn about Z.</param>
    /// <exception cref="ArgumentException">The id is not registered (its landblock unloaded, say), or an argument is invalid.</exception>
    public void MoveMover(uint id, Vector3 position, uint cellId, Quaternion orientation) => Physics.Movers.Move(id, position, cellId, orientation);

    /// <summary>
    /// Publishes the frame's changes to the movers (<see cref="MoverRegistry.Commit"/>): the frame loop calls it once per
    /// frame; every <c>Resolve</c> after it sees them all, doors told to close are closed here once nothing overlaps
    /// them. Frame thread only.
    /// </summary>
    public void CommitMovers() => Physics.Movers.Commit();

    /// <summary>The number of objects registered with each loaded landblock (<c>0xXXYYFFFF</c>), as of its last registration. Frame thread only.</summary>
    public IReadOnlyDictionary<uint, int> ObjectCounts => _objectCounts;

    /// <summary>
    /// The unload path: removes a landblock from the engine (nothing happens if it is not registered), and the movers
    /// whose cell is in it (<see cref="MoverRegistry.RemoveLandblock"/>; gone from the next <see cref="CommitMovers"/>).
    /// </summary>
    internal void UnloadLandblockLocked(uint landblockId)
    {
        uint id = CellIds.LandblockOf(landblockId);
        Physics.Movers.RemoveLandblock(id);
        Physics.RemoveLandblock(id);
        _objectCounts.Remove(id);
        if (_loaded.Remove(id))
        {
            LandblockUnloaded?.Invoke(id);
        }
    }
}

using AcDream.Core.Physics;

namespace AcDream.App.Streaming;

/// <summary>
/// Decides which landblocks to load and unload around the observer. The window is the square of
/// landblocks within <see cref="GameWindow.StreamingRadius"/> of the observer's landblock (3 × 3),
/// clipped to the world; the loaded landblocks outside it are to be unloaded, and those inside it that
/// are neither loaded, in flight nor waiting to be retried are requested, nearest first. A landblock
/// whose load failed waits <see cref="GameWindow.RetryDelayFrames"/> frames before it is requested
/// again. Frame thread only; it touches neither the engine nor the source.
/// </summary>
internal sealed class LandblockStreamer
{
    private readonly HashSet<uint> _window = [];
    private readonly Dictionary<uint, long> _retryAtFrame = [];
    private long _frame;
    private int _centerX, _centerY;

    /// <summary>The landblocks (<c>0xXXYYFFFF</c>) the window holds, as of the last <see cref="MoveTo"/>.</summary>
    public IReadOnlySet<uint> Window => _window;

    /// <summary>Starts a frame: moves the window to the observer's landblock.</summary>
    /// <param name="observerLandblock">The landblock (<c>0xXXYYFFFF</c>) under the observer.</param>
    public void MoveTo(uint observerLandblock)
    {
        _frame++;
        _centerX = CellIds.LandblockX(observerLandblock);
        _centerY = CellIds.LandblockY(observerLandblock);
        _window.Clear();
        for (int dx = -GameWindow.StreamingRadius; dx <= GameWindow.StreamingRadius; dx++)
        {
            for (int dy = -GameWindow.StreamingRadius; dy <= GameWindow.StreamingRadius; dy++)
            {
                int x = _centerX + dx, y = _centerY + dy;
                if (x >= 0 && y >= 0 && x <= PhysicsConstants.MaxLandblockIndex && y <= PhysicsConstants.MaxLandblockIndex)
                {
                    _window.Add(CellIds.Landblock(x, y));
                }
            }
        }
    }

    /// <summary>A landblock of the window failed to load: it waits <see cref="GameWindow.RetryDelayFrames"/> frames (<see cref="MoveTo"/> calls) before it is requested again.</summary>
    public void RetryLater(uint landblockId) => _retryAtFrame[landblockId] = _frame + GameWindow.RetryDelayFrames;

    /// <summary>The landblocks of <paramref name="loaded"/> outside the window: those to unload.</summary>
    public List<uint> LeftBehind(IEnumerable<uint> loaded) => loaded.Where(id => !_window.Contains(id)).ToList();

    /// <summary>
    /// Forgets the waits of landblocks outside the window, and asks <paramref name="loader"/> for the
    /// window's landblocks that are neither in <paramref name="loaded"/>, in flight nor waiting, nearest
    /// first (by distance to the observer's landblock); a landblock requested ends its wait.
    /// </summary>
    public void Request(LandblockLoader loader, IReadOnlySet<uint> loaded)
    {
        foreach (uint id in _retryAtFrame.Keys.Where(id => !_window.Contains(id)).ToList())
        {
            _retryAtFrame.Remove(id);
        }

        List<uint> requested = loader.Request(
            _window,
            id => !loaded.Contains(id) && !(_retryAtFrame.TryGetValue(id, out long retryAt) && _frame < retryAt),
            DistanceSquared);
        foreach (uint id in requested)
        {
            _retryAtFrame.Remove(id);
        }
    }

    private int DistanceSquared(uint id)
    {
        int dx = CellIds.LandblockX(id) - _centerX, dy = CellIds.LandblockY(id) - _centerY;
        return (dx * dx) + (dy * dy);
    }
}
